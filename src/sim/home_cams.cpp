#include "nck/sim/home_cams.hpp"

namespace nck::sim {

HomeCams::HomeCams(const config::Machine& m) {
  for (std::size_t ch = 0; ch < m.channels.size() && ch < config::kMaxChannels; ++ch) {
    const auto& axes = m.channels[ch].axes;
    for (std::size_t j = 0; j < axes.size() && j < kMaxAxes; ++j) {
      const int i = axes[j].axis_index;
      if (i < 0 || static_cast<std::size_t>(i) >= drives::kMaxDrives) continue;
      const config::AxisConfig& ax = m.axes[static_cast<std::size_t>(i)];
      if (ax.homing_method() != config::HomingMethod::cam) continue;
      cams_.push_back(Cam{static_cast<std::uint8_t>(ch), static_cast<std::uint8_t>(j), static_cast<std::uint8_t>(i),
                          static_cast<std::int8_t>(ax.homing_positive ? 1 : -1),
                          ax.gear(ax.initial_gear_stage).reference_pos});
    }
  }
}

void HomeCams::watch(const kernel::TickOutput& out,
                     std::array<kernel::AxisSwitches, drives::kMaxDrives>& axes) const noexcept {
  for (const Cam& c : cams_) {
    axes[c.list].home_cam = c.towards * (out.channels[c.channel].drive_pos(c.axis) - c.edge_mm) >= 0;
  }
}

}  // namespace nck::sim
