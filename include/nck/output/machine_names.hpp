#pragma once
// Output names derived from the machine: trace columns of path axes, and the
// machine's spindles (a spindle known to several channels appears once).
#include <string>
#include <vector>

#include "nck/config/machine.hpp"

namespace nck::app {

struct SpindleName {
  std::string name;
  std::uint32_t log_axis_nr = 0;
  std::size_t channel = 0;  // first channel that lists it
  bool speed_controlled = false;  // antr.operation_mode OPEN_POSITION_LOOP...: trace shows the drive value
};

// Axis designation per channel axis; a designation already used by an earlier
// channel is prefixed with the channel number ("2.X").
std::vector<std::string> path_axis_columns(const config::Machine& m);
std::vector<SpindleName> machine_spindles(const config::Machine& m);

}  // namespace nck::app

namespace nck::app {
// The configured designation of a channel's main spindle ("S1"), or "" if none.
std::string main_spindle_designation(const config::ChannelConfig& ch);
}  // namespace nck::app
