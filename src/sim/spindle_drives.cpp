#include "nck/sim/spindle_drives.hpp"

#include <algorithm>

#include "nck/plc/hli.hpp"

namespace nck::sim {

SpindleDrives::SpindleDrives(const config::Machine& m) {
  const plc::SpindleMap map = plc::build_spindle_map(m);
  count_ = std::min(map.count, kernel::kMaxMachineSpindles);
  const double cycle_s = m.cycle_time_us * 1e-6;
  // The kernel's spindle k is the map's first listing of k.
  for (std::size_t k = 0; k < count_; ++k) {
    const plc::ChannelSpindleRef at = map.first[k];
    const config::ChannelSpindle& sp = m.channels[at.channel - 1u].spindles[static_cast<std::size_t>(at.index)];
    const config::AxisConfig* ax = sp.axis_index >= 0 ? &m.axes[static_cast<std::size_t>(sp.axis_index)] : nullptr;
    drives_[k] = SpindleDrive(SpindleDriveConfig::from(ax, m.sim, cycle_s));
  }
}

spindle::DriveFeedback SpindleDrives::step(std::size_t index, const spindle::DriveCommand& cmd) noexcept {
  if (index >= count_) return spindle::DriveFeedback{};
  return drives_[index].step(cmd);
}

}  // namespace nck::sim
