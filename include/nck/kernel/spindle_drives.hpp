#pragma once
// The spindle drives behind the kernel, for a machine whose drives answer
// within the cycle that commands them: a simulated one (nck/sim's
// SpindleDrives). The kernel steps them where its spindles make their set
// points and judges the answer in the same cycle, as a drive model inside
// the kernel did before it moved to nck/sim (docs/decisions.md, "Spindle drive
// model").
//
// A real machine attaches nothing: its drives' measured values come with
// TickInput::spindle_measured, one cycle after the set point they answer.
#include <cstddef>

#include "nck/spindle/drive_io.hpp"

namespace nck::kernel {

class SpindleDrives {
 public:
  virtual ~SpindleDrives() = default;
  // rt: the drive of kernel spindle `index` takes this cycle's command and
  // returns what it measures at the end of the cycle. Never allocates,
  // locks or throws.
  virtual spindle::DriveFeedback step(std::size_t index, const spindle::DriveCommand& cmd) noexcept = 0;
};

}  // namespace nck::kernel
