#pragma once
// Dwell (G4): a time, or (G4 S..) as many revolutions as a spindle really
// turns (its set-point speed each cycle, so override and ramps count).
#include "nck/kernel/command.hpp"
#include "cycle.hpp"

namespace nck::kernel {

class DwellUnit {
 public:
  // The body of block c begins. rt
  void start(const Command& c) noexcept {
    if (c.kind == CommandKind::dwell) left_s_ = c.dwell_s;
    revs_left_ = c.dwell_revs;
  }
  // One cycle of dwell c; `over` when it has lasted its time. rt
  Fault step(const Command& c, Cycle& cy, bool& over) noexcept;

 private:
  Fault step_revolutions(const Command& c, Cycle& cy, bool& over) noexcept;

  double left_s_ = 0;
  double revs_left_ = 0;
};

}  // namespace nck::kernel
