#include "nck/sim/spindle_drives.hpp"

#include <algorithm>

#include "nck/plc/hli.hpp"

namespace nck::sim {

SpindleDrives::SpindleDrives(const config::Machine& m) {
  const plc::SpindleMap map = plc::build_spindle_map(m);
  count_ = std::min(map.count, kernel::kMaxMachineSpindles);
  std::array<bool, kernel::kMaxMachineSpindles> done{};
  const double cycle_s = m.cycle_time_us * 1e-6;
  // The kernel's spindle k is the first channel spindle the map gives k.
  for (std::size_t c = 0; c < m.channels.size(); ++c)
    for (std::size_t i = 0; i < m.channels[c].spindles.size(); ++i) {
      const std::int8_t k = map.at(c + 1, static_cast<std::int32_t>(i));
      if (k < 0 || static_cast<std::size_t>(k) >= count_ || done[static_cast<std::size_t>(k)]) continue;
      const config::ChannelSpindle& sp = m.channels[c].spindles[i];
      const config::AxisConfig* ax = sp.axis_index >= 0 ? &m.axes[static_cast<std::size_t>(sp.axis_index)] : nullptr;
      drives_[static_cast<std::size_t>(k)] = SpindleDrive(SpindleDriveConfig::from(ax, m.sim, cycle_s));
      done[static_cast<std::size_t>(k)] = true;
    }
}

spindle::DriveFeedback SpindleDrives::step(std::size_t index, const spindle::DriveCommand& cmd) noexcept {
  if (index >= count_) return spindle::DriveFeedback{};
  return drives_[index].step(cmd);
}

}  // namespace nck::sim
