// Handwheel and manual offsets in preparation; see manual_unit.hpp.
#include "nck/prep/units/manual_unit.hpp"

namespace nck::prep {

void ManualUnit::plan(const nc::Block& b, PlannedCommand& c, std::size_t n_axes) const {
  kernel::ManualChange change;
  change.get_offsets = b.hash && std::holds_alternative<nc::GetManualOffsets>(*b.hash);
  if (b.manual_g) {
    // With G201/G202 the axis words select the axes.
    std::uint32_t mask = 0;
    for (std::size_t j = 0; j < n_axes; ++j)
      if (b.axes[j]) mask |= 1u << j;
    if (*b.manual_g == nc::GCode::g201) change.on = mask;
    else change.off = mask != 0 ? mask : ~0u;  // G202 without axes: all
  }
  if (change.on != 0 || change.off != 0 || change.get_offsets) c.attach(change);
}

void ManualUnit::moved(const nc::Block& b, frames::SuppressMask mask, const PlanContext& ctx) {
  const bool leave_out = mask.has(frames::SuppressMask::kManual) || ctx.frames.mcs_active();
  for (std::size_t j = 0; j < ctx.n_axes; ++j) {
    if (!b.axes[j]) continue;
    if (leave_out) axes_ &= ~(1u << j);
    else if (b.modal.absolute) axes_ |= 1u << j;
  }
}

void ManualUnit::stamp(PlannedBlock& out) const {
  for (PlannedCommand& cmd : out) cmd.manual_offset_axes = axes_;
}

}  // namespace nck::prep
