// C-axis machining in the channel (#CAX, facts B12): the main spindle is a
// path axis of the channel while C-axis mode is on. The path interpolator
// computes its set point like any axis (through #FACE / #CYL in place());
// every cycle hands it to the spindle, whose own interpolator then only
// follows (SpindleAxis axis mode). Outside C-axis mode the C axis shows
// where the spindle is, so that C-axis mode starts from there.
#include "channel.hpp"

namespace nck::kernel {

void Channel::set_c_axis(std::int8_t axis, std::int8_t spindle) noexcept {
  const bool ok = axis >= 0 && static_cast<std::size_t>(axis) < n_axes_ && spindle >= 0;
  c_axis_ = ok ? axis : std::int8_t{-1};
  c_spindle_ = ok ? spindle : std::int8_t{-1};
}

// #CAX / #CAX OFF at the start of a command; false when the channel ended.
bool Channel::start_c_axis(const Command& c, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept {
  if (c.cax == Command::CaxOp::none) return true;
  const bool known = c_axis_ >= 0 && c.cax_axis == c_axis_ && c.cax_spindle == c_spindle_ &&
                     static_cast<std::size_t>(c_spindle_) < ctx.spindle_count;
  if (!known) {
    raise(ErrorId::KernelCaxMismatch, kNoMessage, t_s, sink, ctx);
    return false;
  }
  SpindleUnit& u = ctx.spindles[c_spindle_];
  if (c.cax == Command::CaxOp::off) {
    end_c_axis(ctx);
    return true;
  }
  if (!c_axis_on_) {
    if (const spindle::SpindleResult r = u.axis.enter_axis_mode(); !r.ok()) {
      raise(r.id, kNoMessage, t_s, sink, ctx);
      return false;
    }
    c_axis_on_ = true;
    pos_[static_cast<std::size_t>(c_axis_)] = u.axis.status().set_pos_deg;
    c_last_deg_ = pos_[static_cast<std::size_t>(c_axis_)];
  }
  Feedback f;
  f.kind = FeedbackKind::c_axis;
  f.c_axis_deg = pos_[static_cast<std::size_t>(c_axis_)];
  send_feedback(f, t_s, sink, ctx);
  return !done();
}

// After the cycle's path step: the spindle follows C, or C shows the spindle.
void Channel::follow_c_axis(double dt_s, ChannelContext& ctx) noexcept {
  if (c_axis_ < 0 || static_cast<std::size_t>(c_spindle_) >= ctx.spindle_count) return;
  SpindleUnit& u = ctx.spindles[c_spindle_];
  double& c = pos_[static_cast<std::size_t>(c_axis_)];
  if (!c_axis_on_) {
    c = u.axis.status().set_pos_deg;
    return;
  }
  u.axis.axis_set_point(c, dt_s > 0 ? (c - c_last_deg_) / dt_s : 0.0);
  c_last_deg_ = c;
}

void Channel::end_c_axis(ChannelContext& ctx) noexcept {
  if (!c_axis_on_) return;
  c_axis_on_ = false;
  if (static_cast<std::size_t>(c_spindle_) < ctx.spindle_count)
    (void)ctx.spindles[c_spindle_].axis.leave_axis_mode();
}

}  // namespace nck::kernel
