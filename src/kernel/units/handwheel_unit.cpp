#include "handwheel_unit.hpp"

#include <algorithm>

namespace nck::kernel {

void HandwheelUnit::start(const ManualChange* c) noexcept {
  if (c) {
    manual_mask_ = (manual_mask_ | c->on) & ~c->off;
    if (c->get_offsets) fetch_pending_ = true;
  }
  if (manual_mask_ != 0) used_ = true;  // until the first G201 every offset is zero
  share_start_ = share_;
}

// The offset is travelled at a limited speed (docs/decisions.md,
// "Measuring, manual mode, jog and handwheel").
Fault HandwheelUnit::follow_offsets(Cycle& cy, std::uint32_t manual_axes) noexcept {
  // Until the first G201 every handwheel offset is zero: nothing to follow.
  const double step = kHandwheelSpeed_mm_s * cy.dt_s;
  for (std::size_t j = 0; used_ && j < cy.n_axes; ++j) {
    if (((manual_mask_ | manual_axes) >> j) & 1u) target_mm_[j] += cy.in.handwheel_mm[j];
    const double d = target_mm_[j] - offset_mm_[j];
    offset_mm_[j] += std::clamp(d, -step, step);
    in_force_mm_[j] = offset_mm_[j] * share_[j];
  }
  if (!fetch_pending_) return {};
  fetch_pending_ = false;
  Feedback f;
  f.kind = FeedbackKind::manual_offsets;
  f.manual_offsets_mm = offset_mm_;
  return cy.send(f);
}

}  // namespace nck::kernel
