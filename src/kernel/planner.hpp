#pragma once
// Block preparation (setup side, not real-time): turns a decoded block into
// a Command for the cyclic executor — resolves absolute/incremental words to
// machine positions, builds the path segment and its dynamic limits, and
// rejects what this version cannot execute yet with a clear error.
#include <array>
#include <string>
#include <vector>

#include "command.hpp"
#include "nck/config/machine.hpp"
#include "nck/nc/block.hpp"

namespace nck::kernel {

class Planner {
 public:
  // messages: the kernel's text store; error commands index into it.
  Planner(const config::Machine& machine, std::size_t channel_index,
          std::vector<std::string>& messages);

  Command plan(const nc::Block& block, const std::string& file_name);
  Command error_command(ErrorId id, std::string message, std::uint16_t file_id,
                       std::uint32_t line);

  const std::array<double, config::kMaxPathAxes>& programmed_position() const { return pos_; }
  const nc::ModalState& modal() const { return modal_; }
  std::size_t axis_count() const { return n_axes_; }

 private:
  Command plan_motion(const nc::Block& b, Command c, const std::string& file_name);
  bool add_outputs(const nc::Block& b, Command& c);
  std::string unsupported(const nc::Block& b) const;
  int axis_named(const char* name) const;

  const config::Machine& machine_;
  const config::ChannelConfig& channel_;
  std::vector<std::string>& messages_;
  std::size_t n_axes_ = 0;
  std::array<double, config::kMaxPathAxes> pos_{};  // programmed end of the last planned block
  std::array<motion::AxisDynamics, config::kMaxPathAxes> feed_dyn_{}, rapid_dyn_{};
  std::array<double, config::kMaxPathAxes> swe_neg_{}, swe_pos_{};
  nc::ModalState modal_;
};

}  // namespace nck::kernel
