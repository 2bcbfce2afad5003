#pragma once
// An ideal CiA 402 drive: the Device state machine driven by the NC's
// controlword, and a motor that, while operation is enabled, does exactly
// what its mode of operation asks (following error 0); otherwise it holds.
//   cyclic synchronous position (8): stands at the target position;
//   cyclic synchronous velocity (9): turns at the target velocity;
//   homing (6): on the start bit's rising edge it searches for
//     kHomingCycles cycles, standing, then sets its position to 0 (its home
//     offset) and reports homing attained (statusword bits 12 and 10).
// The simulated machine's drives (sim::DriveModels) and the HAL component
// nck_cia402_sim (apps/hal) are this. No allocation, no exception, no clock.
#include <cstdint>

#include "nck/drives/cia402.hpp"
#include "nck/drives/drive_io.hpp"

namespace nck::drives {

class IdealDrive {
 public:
  static constexpr std::uint32_t kHomingCycles = 100;

  // One cycle of cycle_s seconds: the command in, the feedback the NC
  // reads next; `fault` holds the drive's fault input (amplifier fault).
  const DriveFeedback& step(const DriveCommand& cmd, bool fault, double cycle_s) noexcept;
  // A conventional drive (antr_typ 1, no profile): while enabled its motor
  // turns at the target velocity; its position integrates it.
  const DriveFeedback& follow_velocity(const DriveCommand& cmd, double cycle_s) noexcept;
  const DriveFeedback& feedback() const noexcept { return fb_; }
  cia402::State state() const noexcept { return device_.state(); }

 private:
  // Homing mode's part of the statusword (bits 10, 12, 13).
  std::uint16_t home(const DriveCommand& cmd) noexcept;

  cia402::Device device_{2};  // fault reaction: 2 cycles
  DriveFeedback fb_{};
  std::uint16_t last_controlword_ = 0;
  std::uint32_t homing_left_ = 0;  // cycles of the search still to go (0: none runs)
  bool homed_ = false;             // the last homing was attained
};

}  // namespace nck::drives
