// G96 constant cutting speed; see css_unit.hpp.
#include "nck/prep/units/css_unit.hpp"

#include <bit>
#include <fmt/format.h>

#include "nck/kernel/feed_link.hpp"
#include "nck/prep/units/axis_table.hpp"

namespace nck::prep {

PlanResult CssUnit::plan(const nc::Block& b, PlannedCommand& c, const PlanContext& ctx, const MainSpindle& main,
                         double vb_max_rpm) {
  const nc::ModalState& m = b.modal;
  if (m.speed_mode != nc::SpeedMode::g96 || !(m.css_m_min > 0)) return {};
  // The face-turning axis (kenngr.achs_mode 0x40), else the axis named X.
  const std::uint32_t face_axes = ctx.axes.face_axes();
  const int x = face_axes != 0 ? std::countr_zero(face_axes) : ctx.axis_named("X");
  if (x < 0)
    return block_error(ErrorId::KernelCssNoFaceAxis, b, "G96 needs a face axis (achs_mode 0x40, or one named X)");
  const bool new_speed = !on_ || v_m_min_ != m.css_m_min;
  // The radius is the tool tip's: the programmed X plus the zero offsets, i.e.
  // the machine X less the tool offset (docs/decisions.md, "Spindle-path couplings"). Where the
  // turning centre is in machine X: 0 shifted by the tool offset.
  const auto ux = static_cast<std::size_t>(x);
  const motion::AxisVector& pcs = ctx.planned.pcs;
  const double tool_mm = ctx.frames.to_mcs(pcs, frames::SuppressMask::none())[ux] -
                         ctx.frames.to_mcs(pcs, frames::SuppressMask{frames::SuppressMask::kTool})[ux];
  c.css = {true, main.kernel, static_cast<std::int8_t>(x), m.css_m_min, m.max_speed_rpm, tool_mm};
  on_ = true;
  v_m_min_ = m.css_m_min;
  // The start speed comes from where the face axis was last programmed (TF5200 G96).
  const double r_mm = ctx.planned.mcs[ux] - tool_mm;
  if (new_speed && kernel::css_limited(m.css_m_min, r_mm, m.max_speed_rpm, vb_max_rpm))
    (void)c.attach_within(
        kernel::Warning{{ErrorId::KernelCssStartLimited,
                         ctx.store.add_message(fmt::format(
                             "G96 S{}: at radius {:.3f} mm the start speed is limited to {:.1f} rpm", m.css_m_min,
                             r_mm, kernel::css_speed_rpm(m.css_m_min, r_mm, m.max_speed_rpm, vb_max_rpm))),
                         {}}},
        PlannedCommand::kMaxWarnings);
  return {};
}

}  // namespace nck::prep
