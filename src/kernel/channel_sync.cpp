// Synchronisation of a block's spindle and PLC functions with its motion
// (FCT-S1 2.5): what is output when, and what the channel waits for.
#include "channel.hpp"

namespace nck::kernel {
namespace {

FunctionKind function_kind(char fn) {
  return fn == 'S' ? FunctionKind::s : fn == 'H' ? FunctionKind::h : FunctionKind::m;
}

WaitReason reason_of(SpindleWait w) {
  switch (w) {
    case SpindleWait::speed_reached: return WaitReason::speed_reached;
    case SpindleWait::standstill: return WaitReason::standstill;
    case SpindleWait::in_position: return WaitReason::in_position;
    case SpindleWait::gear_change: return WaitReason::gear_change;
    case SpindleWait::none: break;
  }
  return WaitReason::plc_ack;
}

// Is this function issued in `phase` (before or after the motion)?
bool issued_in(SyncPoint sync, SyncPoint phase) {
  const bool after = sync == SyncPoint::after;
  return phase == SyncPoint::after ? after : !after;
}

spindle::SpindleResult run(spindle::SpindleAxis& ax, const SpindleAction& a) noexcept {
  switch (a.op) {
    case SpindleOp::rotate: return ax.rotate(a.rpm, a.g167);
    case SpindleOp::speed: return {};  // only stored: resolved in issue_spindle
    case SpindleOp::stop: return ax.stop();
    case SpindleOp::position: return ax.position(a.pos_deg, a.direction, a.rpm, a.g167);
    case SpindleOp::home: return ax.home();
    case SpindleOp::gear_change: return ax.start_gear_change(a.stage);
    case SpindleOp::load_gear_data: return ax.load_gear_data(a.stage);
    case SpindleOp::accel_weight: return ax.set_accel_weight_pct(a.value);
    case SpindleOp::feedforward_on: return ax.feedforward_on();
    case SpindleOp::feedforward_off: return ax.feedforward_off();
    case SpindleOp::feedforward_weight: return ax.feedforward_weight_pct(a.value);
    case SpindleOp::suppress_override: ax.suppress_override(); return {};
    case SpindleOp::tool_dynamics:
      ax.set_tool_dynamics({a.tool_vb_min_rpm, a.tool_vb_max_rpm, a.tool_a_max_deg_s2});
      return {};
    case SpindleOp::get_dynamic_data: return ax.adopt_tool_dynamics_now();
    case SpindleOp::default_dynamic_data: return ax.default_dynamic_data();
    case SpindleOp::user_function: return {};
  }
  return {};
}

// An S alone, decided from what the spindle really does now: a rotation
// takes the new speed; otherwise it is only stored and nothing moves, so
// there is no speed to wait for (a PLC acknowledgement still is).
SpindleAction resolve_speed(const SpindleUnit& u, const SpindleAction& a) noexcept {
  SpindleAction resolved = a;
  if (const std::optional<double> rpm = speed_change_rpm(u, a.rpm)) {
    resolved.op = SpindleOp::rotate;
    resolved.rpm = *rpm;
  } else {
    resolved.wait = SpindleWait::none;
  }
  return resolved;
}

}  // namespace

std::int8_t Channel::local_index(std::int8_t spindle) const noexcept {
  for (std::size_t i = 0; i < spindles_.size(); ++i)
    if (spindles_[i] == spindle) return static_cast<std::int8_t>(i);
  return -1;
}

// False when the wait does not fit (only late waits can pile up: the
// current block's fit by construction, see channel.hpp).
bool Channel::add_wait(const Wait& w, SyncPoint sync) noexcept {
  Wait x = w;
  x.when = sync;
  switch (sync) {
    case SyncPoint::none: return true;
    case SyncPoint::before: x.when = SyncPoint::before; return waits_.push_back(x);
    case SyncPoint::before_after:
    case SyncPoint::after: x.when = SyncPoint::after; return waits_.push_back(x);
    case SyncPoint::late_motion:
    case SyncPoint::late_explicit: return late_.push_back(x);
  }
  return true;
}

// Late functions synchronise before this block's motion.
void Channel::take_late_waits(SyncPoint which) noexcept {
  std::size_t keep = 0;
  for (std::size_t i = 0; i < late_.size(); ++i) {
    Wait w = late_[i];
    if (w.when == which) {
      w.when = SyncPoint::before;
      (void)waits_.push_back(w);
    } else {
      late_[keep++] = w;
    }
  }
  while (late_.size() > keep) late_.pop_back();
}

void Channel::on_ack(plc::OutputHandle h) noexcept {
  for (Wait& w : waits_)
    if (w.handle == h) w.acked = true;
  for (Wait& w : late_)
    if (w.handle == h) w.acked = true;
}

bool Channel::issue_spindle(const SpindleAction& a, double t_s, TickOutput& sink,
                            ChannelContext& ctx) noexcept {
  if (a.spindle < 0 || static_cast<std::size_t>(a.spindle) >= ctx.spindle_count) return true;
  if (linked_elsewhere(a.spindle, ctx)) {  // only the channel that enabled the link commands it
    Event e = event(EventKind::error, t_s);
    e.id = ErrorId::AxLinkOtherChannel;
    e.message_index = kNoMessage;
    e.spindle = a.spindle;
    sink.emit(e);
    end_program(EndReason::error, t_s, sink, ctx);
    return false;
  }
  SpindleUnit& u = ctx.spindles[a.spindle];
  u.channel = number_;
  u.channel_index = local_index(a.spindle);
  const SpindleAction now = a.op == SpindleOp::speed ? resolve_speed(u, a) : a;
  note_rotation(u, a);  // before the command: a gear change needs the state it interrupts
  const spindle::SpindleResult r = run(u.axis, now);
  if (!r.ok()) {
    raise(r.id, kNoMessage, t_s, sink, ctx);
    return false;
  }
  if (r.warning) {
    Event e = event(EventKind::warning, t_s);
    e.id = r.id;
    e.message_index = kNoMessage;
    e.spindle = a.spindle;
    sink.emit(e);
  }
  if (a.op == SpindleOp::gear_change) {
    u.gear_job = GearJob::approaching;
    u.gear_stage = a.stage;
    u.gear_acked = false;
  }
  Wait w;
  w.spindle = a.spindle;
  w.what = now.wait;
  w.fn = function_kind(a.fn);
  w.fn_number = a.fn_number;
  w.deadline_s = a.ack_timeout_s > 0 ? t_s + a.ack_timeout_s : 0;
  // The gear change's M function goes out when the spindle is at the change
  // position (advance_gear_job); every other output goes now.
  if (a.output && a.op != SpindleOp::gear_change) {
    plc::TechOutput o;
    o.kind = tech_kind(w.fn);
    o.number = a.fn_number;
    o.channel = number_;
    o.spindle = u.channel_index;
    o.value = a.op == SpindleOp::position ? a.pos_deg : now.rpm;
    o.sync = a.sync_bits;
    w.handle = ctx.plc ? ctx.plc->submit(o, sink) : plc::kNoHandle;
    if (w.handle == plc::kNoHandle) {
      raise(ErrorId::PlcOutputQueueFull, kNoMessage, t_s, sink, ctx);
      return false;
    }
    Event e = event(EventKind::plc_out, t_s);
    e.fn = w.fn;
    e.fn_number = a.fn_number;
    e.spindle = a.spindle;
    e.value = o.value;
    e.sync = a.sync_bits;
    sink.emit(e);
  }
  if ((w.what != SpindleWait::none || w.handle != plc::kNoHandle) && !add_wait(w, a.sync)) {
    raise(ErrorId::KernelWaitOverflow, kNoMessage, t_s, sink, ctx);
    return false;
  }
  return true;
}

void Channel::issue_output(const Output& o, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept {
  plc::TechOutput t;
  t.kind = tech_kind(o.fn);
  t.number = o.number;
  t.channel = number_;
  t.sync = o.sync;
  Wait w;
  w.fn = o.fn;
  w.fn_number = o.number;
  w.deadline_s = o.ack_timeout_s > 0 ? t_s + o.ack_timeout_s : 0;
  w.handle = ctx.plc ? ctx.plc->submit(t, sink) : plc::kNoHandle;
  if (w.handle == plc::kNoHandle) {
    raise(ErrorId::PlcOutputQueueFull, kNoMessage, t_s, sink, ctx);
    return;
  }
  Event e = event(EventKind::plc_out, t_s);
  e.fn = o.fn;
  e.fn_number = o.number;
  e.sync = o.sync;
  sink.emit(e);
  if (!add_wait(w, sync_point(o.sync).value_or(SyncPoint::none)))
    raise(ErrorId::KernelWaitOverflow, kNoMessage, t_s, sink, ctx);
}

void Channel::issue_all(SyncPoint phase, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept {
  for (const Output& o : current_.outputs) {
    if (!issued_in(sync_point(o.sync).value_or(SyncPoint::none), phase)) continue;
    issue_output(o, t_s, sink, ctx);
    if (done()) return;
  }
  next_action_ = 0;
  (void)issue_spindle_actions(phase, t_s, sink, ctx);
}

// Issues the block's spindle actions of `phase` from next_action_ on. A gear
// change must be finished before the speed of the new stage is commanded:
// the actions after it wait (false = some are left for later).
bool Channel::issue_spindle_actions(SyncPoint phase, double t_s, TickOutput& sink,
                                    ChannelContext& ctx) noexcept {
  const auto& actions = current_.spindle_actions;
  while (next_action_ < actions.size()) {
    const SpindleAction& a = actions[next_action_++];
    if (!issued_in(a.sync, phase)) continue;
    if (!issue_spindle(a, t_s, sink, ctx)) return true;
    if (a.op == SpindleOp::gear_change) return next_action_ >= actions.size();
  }
  return true;
}

bool Channel::satisfied(const Wait& w, const ChannelContext& ctx) const noexcept {
  if (w.handle != plc::kNoHandle && !w.acked) return false;
  if (w.spindle < 0 || static_cast<std::size_t>(w.spindle) >= ctx.spindle_count) return true;
  const SpindleUnit& u = ctx.spindles[w.spindle];
  const spindle::SpindleStatus& s = u.axis.status();
  switch (w.what) {
    case SpindleWait::speed_reached: return s.speed_reached;
    case SpindleWait::standstill: return s.standstill;
    case SpindleWait::in_position: return s.in_position;
    case SpindleWait::gear_change: return u.gear_job == GearJob::done;
    case SpindleWait::none: break;
  }
  return true;
}

// Checks the waits of `phase`; announces new ones, ends satisfied ones, and
// raises a timeout or a spindle error. True when none is left.
bool Channel::waits_done(SyncPoint phase, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept {
  std::size_t keep = 0;
  for (std::size_t i = 0; i < waits_.size(); ++i) {
    Wait w = waits_[i];
    if (w.when != phase) {
      waits_[keep++] = w;
      continue;
    }
    Event e = event(EventKind::wait, t_s);
    e.spindle = w.spindle;
    e.fn = w.fn;
    e.fn_number = w.fn_number;
    e.wait_reason = static_cast<std::uint8_t>(w.reason);
    const bool acked = w.handle == plc::kNoHandle || w.acked;
    const WaitReason now = acked ? reason_of(w.what) : WaitReason::plc_ack;
    if (satisfied(w, ctx) || (w.announced && now != w.reason)) {
      if (w.announced) {  // ends the wait, or its reason changes (PLC acknowledged, speed not yet)
        e.kind = EventKind::wait_end;
        sink.emit(e);
        w.announced = false;
      }
      if (satisfied(w, ctx)) continue;
    }
    e.kind = EventKind::wait;
    e.wait_reason = static_cast<std::uint8_t>(now);
    w.reason = now;
    if (w.spindle >= 0 && static_cast<std::size_t>(w.spindle) < ctx.spindle_count) {
      const spindle::SpindleStatus& s = ctx.spindles[w.spindle].axis.status();
      if (s.mode == spindle::SpindleMode::error) {
        raise(s.error, kNoMessage, t_s, sink, ctx);
        return false;
      }
    }
    if (w.deadline_s > 0 && t_s >= w.deadline_s && !acked) {
      raise(ErrorId::PlcAckTimeout, kNoMessage, t_s, sink, ctx);
      return false;
    }
    if (!w.announced) {
      sink.emit(e);
      w.announced = true;
    }
    waits_[keep++] = w;
  }
  const std::size_t left = keep;
  while (waits_.size() > keep) waits_.pop_back();
  for (std::size_t i = 0; i < left; ++i)
    if (waits_[i].when == phase) return false;
  return true;
}

}  // namespace nck::kernel
