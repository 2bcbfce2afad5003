#pragma once
// The simulated machine's spindle drives, one per kernel spindle (in the
// kernel's order, plc::build_spindle_map), stepped by the kernel through
// kernel::SpindleDrives where its spindles make their set points, so that
// the measured values judge the set point of the same cycle.
#include <array>
#include <cstddef>

#include "nck/config/machine.hpp"
#include "nck/kernel/spindle_drives.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/sim/spindle_drive.hpp"

namespace nck::sim {

class SpindleDrives final : public kernel::SpindleDrives {
 public:
  SpindleDrives() = default;
  explicit SpindleDrives(const config::Machine& m);  // setup

  // rt
  spindle::DriveFeedback step(std::size_t index, const spindle::DriveCommand& cmd) noexcept override;

  std::size_t count() const noexcept { return count_; }
  const SpindleDrive& drive(std::size_t index) const { return drives_.at(index); }

 private:
  std::array<SpindleDrive, kernel::kMaxMachineSpindles> drives_{};
  std::size_t count_ = 0;
};

}  // namespace nck::sim
