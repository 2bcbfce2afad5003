#pragma once
// The channel's main spindle as the spindle-path couplings see it (G95,
// G96, G33, G63, G331/G332, G4 S): the channel spindle with log_achs_nr =
// main_spindle_ax_nr, else the first one.
#include <cstdint>
#include <vector>

#include "nck/config/machine.hpp"

namespace nck::prep {

struct MainSpindle {
  std::int8_t kernel = -1;  // kernel spindle index, -1: the channel has none
  std::size_t list_index = 0;  // index in the channel's spindle list

  // spindles: the kernel spindle index of each of the channel's spindles.
  static MainSpindle find(const config::ChannelConfig& channel, const std::vector<std::int8_t>& spindles);
  bool exists() const { return kernel >= 0; }
  // The top speed of gear stage `stage` of its axis list, in rpm (0 = none).
  double vb_max_rpm(const config::Machine& machine, const config::ChannelConfig& channel,
                    std::uint32_t stage) const;
  // The same in the gear stage a spindle works in as an axis (P-AXIS-00052,
  // kenngr.def_cax_gear_st: #CAX and G63, FCT-S1 2.8.6).
  double axis_vb_max_rpm(const config::Machine& machine, const config::ChannelConfig& channel) const;
};

}  // namespace nck::prep
