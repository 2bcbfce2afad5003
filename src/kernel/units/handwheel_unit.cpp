#include "handwheel_unit.hpp"

#include <algorithm>

namespace nck::kernel {

void HandwheelUnit::start(const Command& c) noexcept {
  manual_mask_ = (manual_mask_ | c.manual_on) & ~c.manual_off;
  if (manual_mask_ != 0) used_ = true;  // until the first G201 every offset is zero
  if (c.get_manual_offsets) fetch_pending_ = true;
  share_start_ = share_;
}

// A motion block takes the handwheel offset of its axes in or out (command
// manual_offset_axes) in step with its path, 0 at its start and 1 at its
// end, so the set point never jumps by the offset.
void HandwheelUnit::blend(const Command& c, double s_mm, std::size_t n_axes) noexcept {
  const double length = c.segment.length();
  const double fraction = length > 0 ? std::clamp(s_mm / length, 0.0, 1.0) : 1.0;
  for (std::size_t j = 0; j < n_axes; ++j) {
    const double target = (c.manual_offset_axes >> j) & 1u ? 1.0 : 0.0;
    share_[j] = share_start_[j] + (target - share_start_[j]) * fraction;
  }
}

// The offset is travelled at a limited speed (docs/decisions.md).
Fault HandwheelUnit::follow(Cycle& cy) noexcept {
  // Until the first G201 every handwheel offset is zero: nothing to follow.
  const double step = kHandwheelSpeed_mm_s * cy.dt_s;
  for (std::size_t j = 0; used_ && j < cy.n_axes; ++j) {
    if ((manual_mask_ >> j) & 1u) target_mm_[j] += cy.in.handwheel_mm[j];
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
