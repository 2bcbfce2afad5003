#include "dwell_unit.hpp"

#include <cmath>

namespace nck::kernel {

Fault DwellUnit::step(const Dwell& d, Cycle& cy, bool& over) noexcept {
  if (d.revolutions) return step_revolutions(*d.revolutions, cy, over);
  left_s_ -= cy.dt_s;
  // Half a cycle of tolerance so a dwell of k cycles takes exactly k cycles.
  over = left_s_ <= 0.5 * cy.dt_s;
  return {};
}

// A spindle that stands when the dwell begins would never end it: an error.
Fault DwellUnit::step_revolutions(const Dwell::Revolutions& r, Cycle& cy, bool& over) noexcept {
  const SpindleUnit* u = cy.machine.spindle(r.spindle);
  const double rpm = u ? std::fabs(u->axis.status().set_rpm) : 0.0;
  if (rpm <= 0 && revs_left_ == r.revs && r.revs > 0) return {ErrorId::KernelDwellSpindleStopped};
  revs_left_ -= rpm / 60.0 * cy.dt_s;
  // Half a cycle of tolerance, as for a dwell in seconds.
  over = revs_left_ <= 0.5 * rpm / 60.0 * cy.dt_s;
  return {};
}

}  // namespace nck::kernel
