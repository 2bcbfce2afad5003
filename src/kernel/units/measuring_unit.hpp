#pragma once
// Measuring (G100): the motion ends where the probe switched (the axes stop
// at the latched point and the rest of the path is dropped: measuring type
// 1) or, without a switch, at its end point. The probe reports a switch one
// cycle after it happened, so a run that reached its end point looks one
// cycle longer. Preparation learns the result through the feedback queue.
#include "nck/kernel/command.hpp"
#include "cycle.hpp"

namespace nck::kernel {

class MeasuringUnit {
 public:
  // Before the path's step: does the G100 run c end in this cycle? A switch
  // counts once this run has moved (not one left from the block before). rt
  bool run_ends(const Motion& m, const ChannelInput& in) const noexcept {
    return m.measure && (awaiting_probe_ || (in.probe_switched && probe_armed_));
  }
  // The path of motion m stepped: a probe switch from now on is its own. rt
  void stepped(const Motion& m) noexcept { probe_armed_ = m.measure; }
  // Motion m reached its end point: true for a G100 run (it waits one more
  // cycle for the probe). rt
  bool reached_end(const Motion& m) noexcept {
    if (m.measure) awaiting_probe_ = true;
    return m.measure;
  }
  // Ends the run: the set point pos_mm goes to the latched point when the
  // probe switched (machine position less the handwheel offset manual_mm),
  // and the result goes to preparation. rt
  Fault end_run(motion::AxisVector& pos_mm, const motion::AxisVector& manual_mm, Cycle& cy) noexcept;

 private:
  bool probe_armed_ = false;     // the G100 run has moved: a probe switch is its own
  bool awaiting_probe_ = false;  // G100 reached its end point: one more cycle for the probe
};

}  // namespace nck::kernel
