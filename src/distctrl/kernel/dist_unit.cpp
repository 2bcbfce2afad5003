// #DIST CTRL in the channel; see dist_unit.hpp.
#include "dist_unit.hpp"

namespace nck::kernel {

Fault DistUnit::start(const DistChange& c, Cycle& cy) noexcept {
  // The tool axis is fixed while the offset is in the set point: a plane
  // change moves it only once distance control is off again.
  if (!ctrl_.engaged() && ctrl_.offset_mm() == 0) axis_ = c.axis;
  if (axis_ < 0) axis_ = c.axis;
  check_sw_ = c.sw_limits_mm.has_value();
  if (c.sw_limits_mm) sw_limits_mm_ = *c.sw_limits_mm;
  if (c.source) source_ = *c.source;
  if (c.variable[0] != '\0') var_ = c.variable;
  const ErrorId e = ctrl_.apply(c.sw);
  note_state(cy);
  return {e};
}

Fault DistUnit::step(const motion::AxisVector& pos_mm, Cycle& cy) noexcept {
  const double prog_mm = pos_mm[static_cast<std::size_t>(axis_)];
  distctrl::Sample smp{cy.in.dist_sensor_valid, cy.in.dist_sensor_mm};
  if (source_ == DistChange::Source::variable) {  // a variable not (yet) written counts as no value
    smp.valid = false;
    for (const ChannelVariable& v : cy.in.variables)
      if (v.name == var_) smp = {true, v.value};
  }
  ErrorId e = ctrl_.step(smp, prog_mm);
  // P-CHAN-00809: the set point with the offset stays inside the software limits.
  if (e == ErrorId{} && check_sw_) e = ctrl_.clamp_to(sw_limits_mm_[0] - prog_mm, sw_limits_mm_[1] - prog_mm);
  note_state(cy);
  return {e};
}

// One dist_ctrl event per state change.
void DistUnit::note_state(Cycle& cy) noexcept {
  if (ctrl_.state() == reported_) return;
  reported_ = ctrl_.state();
  cy.emit(distctrl::StateEvent{reported_});
}

bool DistUnit::wind_down() noexcept {
  if (ctrl_.engaged() && ctrl_.state() != distctrl::State::turning_off) {
    distctrl::Switch off;
    off.op = distctrl::Op::off;
    (void)ctrl_.apply(off);
  }
  return ctrl_.state() == distctrl::State::turning_off;
}

void DistUnit::end(EndReason reason, Cycle& cy) noexcept {
  ctrl_.stop(reason != EndReason::error);
  note_state(cy);
}

void DistUnit::add_offset(motion::AxisVector& m, std::size_t n_axes) const noexcept {
  if (axis_ >= 0 && static_cast<std::size_t>(axis_) < n_axes) m[static_cast<std::size_t>(axis_)] += ctrl_.offset_mm();
}

void DistUnit::output(ChannelOutput& out, std::size_t n_axes) const noexcept {
  out.dist_offset_mm = ctrl_.offset_mm();
  out.dist_sensor_mm = ctrl_.sensor_mm();
  out.dist_error_mm = ctrl_.dist_error_mm();
  out.dist_state = ctrl_.state();
  out.dist_axis = axis_;
  if (axis_ >= 0 && static_cast<std::size_t>(axis_) < n_axes)
    out.axis_mcs[static_cast<std::size_t>(axis_)] += ctrl_.offset_mm();
}

}  // namespace nck::kernel
