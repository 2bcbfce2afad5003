#pragma once
// The pre-flight check's view of the spindle speed limits (program_check):
// the kernel's spindle caps a commanded speed at the gear stage's maximum
// (getriebe[i].dynamik.vb_max) and the active tool's (wz[i].vb_max), and
// warns 950007 when it does. Without a kernel, the check follows the
// spindle actions of the planned commands — gear stage, tool data, rotation
// — and gives the same warning, with the speed and the maximum, at the block
// that commands the speed. A spindle that cannot position (config::
// knows_position) is error 70252 at an M19 or G74, as in the run.
#include <cstdint>
#include <optional>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/prep/planned_command.hpp"

namespace nck::prep {

class SpindleLimitCheck {
 public:
  // kernel_spindles[i]: the kernel index of channel ch's spindel[i].
  SpindleLimitCheck(const config::Machine& m, std::size_t ch, const std::vector<std::int8_t>& kernel_spindles);

  // The actions of c, in order; a speed beyond the maximum in force is a
  // warning at c's line (file: the caller's).
  void check(const PlannedCommand& c, std::vector<Diagnostic>& out);

 private:
  struct Tracked {
    std::int8_t kernel = -1;
    const config::ChannelSpindle* channel = nullptr;
    const config::AxisConfig* axis = nullptr;  // nullptr: a PLC spindle (the PLC limits it)
    std::uint32_t stage = 1;
    double tool_max_rpm = 0;  // 0: no tool limit
    std::optional<double> pending_tool_max_rpm;  // a tool's limit waiting for standstill
    bool rotating = false;
  };
  Tracked* find(std::int8_t kernel);
  std::optional<Diagnostic> speed_check(const Tracked& s, double rpm, std::uint32_t line) const;
  std::optional<Diagnostic> position_check(const Tracked& s, kernel::SpindleOp op, std::uint32_t line) const;

  std::vector<Tracked> spindles_;
};

}  // namespace nck::prep
