// 3D distance control in the channel (SPEC 3.7): #DIST CTRL commands switch
// the controller at their block's start; every cycle it takes the sensor
// value from TickInput and its offset is added to the tool axis's set point
// (never to the path: the program's positions stay what they were).
#include "channel.hpp"

namespace nck::kernel {

void Channel::set_dist_ctrl(const distctrl::Settings& s, double dt_s) noexcept { dist_.setup(s, dt_s); }

bool Channel::take_dist(const Command& c, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept {
  if (!c.dist.any()) return true;
  // The tool axis is fixed while the offset is in the set point: a plane
  // change moves it only once distance control is off again.
  if (!dist_.engaged() && dist_.offset_mm() == 0) dist_axis_ = c.dist_axis;
  if (dist_axis_ < 0) dist_axis_ = c.dist_axis;
  dist_check_sw_ = c.dist_check_sw;
  if (c.dist_source >= 0) dist_source_ = c.dist_source;
  if (c.dist_var[0] != '\0') dist_var_ = c.dist_var;
  dist_sw_neg_mm_ = c.dist_sw_neg_mm;
  dist_sw_pos_mm_ = c.dist_sw_pos_mm;
  const ErrorId e = dist_.apply(c.dist);
  note_dist_state(t_s, sink);
  if (e == ErrorId{}) return true;
  raise(e, kNoMessage, t_s, sink, ctx);
  return false;
}

void Channel::run_dist(double t_s, const ChannelInput& in, TickOutput& sink, ChannelContext& ctx) noexcept {
  if (done() || !dist_.engaged() || dist_axis_ < 0) {
    note_dist_state(t_s, sink);
    return;
  }
  const double prog_mm = pos_[static_cast<std::size_t>(dist_axis_)];
  distctrl::Sample smp{in.dist_sensor_valid, in.dist_sensor_mm};
  if (dist_source_ == 1) {  // a variable not (yet) written counts as no value
    smp.valid = false;
    for (const ChannelVariable& v : in.variables)
      if (v.name == dist_var_) smp = {true, v.value};
  }
  ErrorId e = dist_.step(smp, prog_mm);
  // P-CHAN-00809: the set point with the offset stays inside the software limits.
  if (e == ErrorId{} && dist_check_sw_) e = dist_.clamp_to(dist_sw_neg_mm_ - prog_mm, dist_sw_pos_mm_ - prog_mm);
  note_dist_state(t_s, sink);
  if (e != ErrorId{}) raise(e, kNoMessage, t_s, sink, ctx);
}

// One dist_ctrl event per state change.
void Channel::note_dist_state(double t_s, TickOutput& sink) noexcept {
  if (dist_.state() == dist_reported_) return;
  dist_reported_ = dist_.state();
  Event e = event(EventKind::dist_ctrl, t_s);
  e.dist_state = static_cast<std::uint8_t>(dist_reported_);
  sink.emit(e);
}

// At program end: switch off, and report whether the offset is still being
// travelled out (the end block waits for it).
bool Channel::dist_wind_down() noexcept {
  if (dist_.engaged() && dist_.state() != distctrl::State::turning_off) {
    distctrl::Switch off;
    off.op = distctrl::Op::off;
    (void)dist_.apply(off);
  }
  return dist_.state() == distctrl::State::turning_off;
}

void Channel::dist_output(ChannelOutput& out) const noexcept {
  out.dist_offset_mm = dist_.offset_mm();
  out.dist_sensor_mm = dist_.sensor_mm();
  out.dist_error_mm = dist_.dist_error_mm();
  out.dist_state = static_cast<std::uint8_t>(dist_.state());
  out.dist_axis = dist_axis_;
  if (dist_axis_ >= 0 && static_cast<std::size_t>(dist_axis_) < n_axes_)
    out.axis_mcs[static_cast<std::size_t>(dist_axis_)] += dist_.offset_mm();
}

}  // namespace nck::kernel
