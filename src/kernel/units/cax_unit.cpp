#include "cax_unit.hpp"

namespace nck::kernel {

void CaxUnit::setup(std::int8_t axis, std::int8_t spindle, std::size_t n_axes) noexcept {
  const bool ok = axis >= 0 && static_cast<std::size_t>(axis) < n_axes && spindle >= 0;
  axis_ = ok ? axis : std::int8_t{-1};
  spindle_ = ok ? spindle : std::int8_t{-1};
}

Fault CaxUnit::start(const CaxChange& c, motion::AxisVector& pos_mm, Cycle& cy) noexcept {
  const bool known = axis_ >= 0 && c.axis == axis_ && c.spindle == spindle_ &&
                     static_cast<std::size_t>(spindle_) < cy.machine.spindle_count;
  if (!known) return {ErrorId::KernelCaxMismatch};
  SpindleUnit& u = cy.machine.spindles[spindle_];
  if (!c.on) {
    end(cy.machine);
    return {};
  }
  double& c_deg = pos_mm[static_cast<std::size_t>(axis_)];
  if (!on_) {
    if (const spindle::SpindleResult r = u.axis.enter_axis_mode(); !r.ok()) return {r.id};
    on_ = true;
    c_deg = u.axis.status().set_pos_deg;
    last_deg_ = c_deg;
  }
  Feedback f;
  f.kind = FeedbackKind::c_axis;
  f.c_axis_deg = c_deg;
  return cy.send(f);
}

void CaxUnit::follow_c(double dt_s, motion::AxisVector& pos_mm, ChannelContext& ctx) noexcept {
  if (static_cast<std::size_t>(spindle_) >= ctx.spindle_count) return;
  SpindleUnit& u = ctx.spindles[spindle_];
  double& c = pos_mm[static_cast<std::size_t>(axis_)];
  if (!on_) {
    c = u.axis.status().set_pos_deg;
    return;
  }
  u.axis.axis_set_point(c, dt_s > 0 ? (c - last_deg_) / dt_s : 0.0);
  last_deg_ = c;
}

void CaxUnit::end(ChannelContext& ctx) noexcept {
  if (!on_) return;
  on_ = false;
  if (static_cast<std::size_t>(spindle_) < ctx.spindle_count) (void)ctx.spindles[spindle_].axis.leave_axis_mode();
}

}  // namespace nck::kernel
