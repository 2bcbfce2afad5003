#pragma once
// Dwell (G4): a time, or (G4 S..) as many revolutions as a spindle really
// turns (its set-point speed each cycle, so override and ramps count).
#include "nck/kernel/command.hpp"
#include "cycle.hpp"

namespace nck::kernel {

class DwellUnit {
 public:
  // Dwell d begins. rt
  void start(const Dwell& d) noexcept {
    left_s_ = d.time_s;
    revs_left_ = d.revolutions ? d.revolutions->revs : 0.0;
  }
  // One cycle of dwell d; `over` when it has lasted its time. rt
  Fault step(const Dwell& d, Cycle& cy, bool& over) noexcept;

 private:
  Fault step_revolutions(const Dwell::Revolutions& r, Cycle& cy, bool& over) noexcept;

  double left_s_ = 0;
  double revs_left_ = 0;
};

}  // namespace nck::kernel
