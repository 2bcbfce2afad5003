#include "measuring_unit.hpp"

namespace nck::kernel {

Fault MeasuringUnit::end_run(motion::AxisVector& pos_mm, const motion::AxisVector& manual_mm,
                             Cycle& cy) noexcept {
  Feedback f;
  f.kind = FeedbackKind::measured;
  f.measure.triggered = cy.in.probe_switched && probe_armed_;
  if (f.measure.triggered)
    for (std::size_t j = 0; j < cy.n_axes; ++j) pos_mm[j] = cy.in.probe_latched_mcs[j] - manual_mm[j];
  f.measure.mcs = pos_mm;
  awaiting_probe_ = false;
  probe_armed_ = false;
  return cy.send(f);
}

}  // namespace nck::kernel
