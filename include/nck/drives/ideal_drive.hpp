#pragma once
// An ideal CiA 402 drive: the Device state machine driven by the NC's
// controlword, and a motor that, while operation is enabled, stands exactly
// where the NC commands it (following error 0); otherwise it holds. The
// simulated machine's drives (sim::Cia402Drives) and the HAL component
// nck_cia402_sim (apps/hal) are this. No allocation, no exception, no clock.
#include "nck/drives/cia402.hpp"
#include "nck/drives/drive_io.hpp"

namespace nck::drives {

class IdealDrive {
 public:
  // One cycle: the command in, the feedback the NC reads next; `fault`
  // holds the drive's fault input (amplifier fault) while set.
  const DriveFeedback& step(const DriveCommand& cmd, bool fault) noexcept;
  const DriveFeedback& feedback() const noexcept { return fb_; }
  cia402::State state() const noexcept { return device_.state(); }

 private:
  cia402::Device device_{2};  // fault reaction: 2 cycles
  DriveFeedback fb_{};
};

}  // namespace nck::drives
