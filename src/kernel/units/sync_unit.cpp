#include "sync_unit.hpp"

#include "axis_link_unit.hpp"

namespace nck::kernel {
namespace {

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

std::int8_t local_index(std::int8_t spindle, const Cycle& cy) noexcept {
  for (std::size_t i = 0; i < cy.spindles.size(); ++i)
    if (cy.spindles[i] == spindle) return static_cast<std::int8_t>(i);
  return -1;
}

bool satisfied_by(const SpindleUnit& u, SpindleWait what) noexcept {
  const spindle::SpindleStatus& s = u.axis.status();
  switch (what) {
    case SpindleWait::speed_reached: return s.speed_reached;
    case SpindleWait::standstill: return s.standstill;
    case SpindleWait::in_position: return s.in_position;
    case SpindleWait::gear_change: return u.gear_job == GearJob::done;
    case SpindleWait::none: break;
  }
  return true;
}

}  // namespace

// False when the wait does not fit (only late waits can pile up: the
// current block's fit by construction, see sync_unit.hpp).
bool SyncUnit::add_wait(const Wait& w, SyncPoint sync) noexcept {
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

void SyncUnit::start_block(const Command& c) noexcept {
  outputs_.clear();
  actions_.clear();
  if (c.feed_motion) take_late_waits(SyncPoint::late_motion);
  if (c.expl_syn) take_late_waits(SyncPoint::late_explicit);
}

void SyncUnit::take_late_waits(SyncPoint which) noexcept {
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

void SyncUnit::on_ack(plc::OutputHandle h) noexcept {
  for (Wait& w : waits_)
    if (w.handle == h) w.acked = true;
  for (Wait& w : late_)
    if (w.handle == h) w.acked = true;
}

Fault SyncUnit::issue_spindle(const SpindleAction& a, Cycle& cy) noexcept {
  SpindleUnit* target = cy.machine.spindle(a.spindle);
  if (!target) return {};
  SpindleUnit& u = *target;
  if (linked_to_other_channel(u, cy.channel)) {  // only the channel that enabled the link commands it
    cy.emit(ev::Error{{ErrorId::AxLinkOtherChannel, std::nullopt, a.spindle}});
    return {ErrorId::AxLinkOtherChannel, true};
  }
  u.channel = cy.channel;
  u.channel_index = local_index(a.spindle, cy);
  const SpindleAction now = a.op == SpindleOp::speed ? resolve_speed(u, a) : a;
  note_rotation(u, a);  // before the command: a gear change needs the state it interrupts
  const spindle::SpindleResult r = run(u.axis, now);
  if (!r.ok()) return {r.id};
  if (r.warning) {
    cy.emit(ev::Warning{{r.id, std::nullopt, a.spindle}});
  }
  if (a.op == SpindleOp::gear_change) {
    u.gear_job = GearJob::approaching;
    u.gear_stage = a.stage;
    u.gear_acked = false;
  }
  Wait w;
  w.spindle = a.spindle;
  w.what = now.wait;
  w.fn = a.fn;
  w.fn_number = a.fn_number;
  w.deadline_s = a.ack_timeout_s > 0 ? cy.t_s + a.ack_timeout_s : 0;
  // The gear change's M function goes out when the spindle is at the change
  // position (advance_gear_job); every other output goes now.
  if (a.output && a.op != SpindleOp::gear_change)
    if (const Fault f = output_spindle_function(a, now, w, cy); f.any()) return f;
  if ((w.what != SpindleWait::none || w.handle != plc::kNoHandle) && !add_wait(w, a.sync))
    return {ErrorId::KernelWaitOverflow};
  return {};
}

// The PLC output of spindle action a (`now` as resolved); its handle goes to w.
Fault SyncUnit::output_spindle_function(const SpindleAction& a, const SpindleAction& now, Wait& w,
                                        Cycle& cy) noexcept {
  const SpindleUnit& u = cy.machine.spindles[a.spindle];
  plc::TechOutput o;
  o.kind = w.fn;
  o.number = a.fn_number;
  o.channel = cy.channel;
  o.spindle = u.channel_index;
  o.value = a.op == SpindleOp::position ? a.pos_deg : now.rpm;
  o.sync = a.sync_bits;
  w.handle = cy.machine.plc ? cy.machine.plc->submit(o, cy.sink) : plc::kNoHandle;
  if (w.handle == plc::kNoHandle) return {ErrorId::PlcOutputQueueFull};
  cy.emit(ev::PlcOut{w.fn, a.fn_number, ev::spindle_or_none(a.spindle), o.value, a.sync_bits});
  return {};
}

Fault SyncUnit::issue_output(const Output& o, Cycle& cy) noexcept {
  plc::TechOutput t;
  t.kind = o.fn;
  t.number = o.number;
  t.channel = cy.channel;
  t.sync = o.sync;
  t.value = o.value.value_or(0);
  Wait w;
  w.fn = o.fn;
  w.fn_number = o.number;
  w.deadline_s = o.ack_timeout_s > 0 ? cy.t_s + o.ack_timeout_s : 0;
  w.handle = cy.machine.plc ? cy.machine.plc->submit(t, cy.sink) : plc::kNoHandle;
  if (w.handle == plc::kNoHandle) return {ErrorId::PlcOutputQueueFull};
  cy.emit(ev::PlcOut{o.fn, o.number, std::nullopt, 0, o.sync, o.value.value_or(ev::kNoAddValue)});
  if (!add_wait(w, sync_point(o.sync).value_or(SyncPoint::none))) return {ErrorId::KernelWaitOverflow};
  return {};
}

Fault SyncUnit::issue_all(SyncPoint phase, Cycle& cy) noexcept {
  for (const Output& o : outputs_) {
    if (!issued_in(sync_point(o.sync).value_or(SyncPoint::none), phase)) continue;
    if (const Fault f = issue_output(o, cy); f.any()) return f;
  }
  next_action_ = 0;
  return issue_spindle_actions(phase, cy);
}

// Issues the block's spindle actions of `phase` from next_action_ on. A gear
// change must be finished before the speed of the new stage is commanded:
// the actions after it wait.
Fault SyncUnit::issue_spindle_actions(SyncPoint phase, Cycle& cy) noexcept {
  const auto& actions = actions_;
  while (next_action_ < actions.size()) {
    const SpindleAction& a = actions[next_action_++];
    if (!issued_in(a.sync, phase)) continue;
    if (const Fault f = issue_spindle(a, cy); f.any()) return f;
    if (a.op == SpindleOp::gear_change) return {};
  }
  return {};
}

Fault SyncUnit::update_waits(SyncPoint phase, Cycle& cy) noexcept {
  std::size_t keep = 0;
  for (std::size_t i = 0; i < waits_.size(); ++i) {
    Wait w = waits_[i];
    bool stays = true;
    if (w.when == phase)
      if (const Fault f = check(w, stays, cy); f.any()) return f;
    if (stays) waits_[keep++] = w;
  }
  while (waits_.size() > keep) waits_.pop_back();
  return {};
}

bool SyncUnit::waiting(SyncPoint phase) const noexcept {
  for (const Wait& w : waits_)
    if (w.when == phase) return true;
  return false;
}

WaitReason SyncUnit::reason(SyncPoint phase) const noexcept {
  for (const Wait& w : waits_)
    if (w.when == phase) return w.reason;
  return WaitReason::plc_ack;
}

// One wait of the phase checked: announced when new, ended when satisfied
// (stays = false), or a timeout or spindle error.
Fault SyncUnit::check(Wait& w, bool& stays, Cycle& cy) noexcept {
  const SpindleUnit* u = cy.machine.spindle(w.spindle);
  const bool acked = w.handle == plc::kNoHandle || w.acked;
  const bool satisfied = acked && (!u || satisfied_by(*u, w.what));
  ev::Wait e{w.reason, ev::spindle_or_none(w.spindle), w.fn, w.fn_number};
  const WaitReason now = acked ? reason_of(w.what) : WaitReason::plc_ack;
  if (satisfied || (w.announced && now != w.reason)) {
    if (w.announced) {  // ends the wait, or its reason changes (PLC acknowledged, speed not yet)
      cy.emit(ev::WaitEnd{e});
      w.announced = false;
    }
    if (satisfied) {
      stays = false;
      return {};
    }
  }
  e.reason = now;
  w.reason = now;
  if (u && u->axis.status().mode == spindle::SpindleMode::error) return {u->axis.status().error};
  if (w.deadline_s > 0 && cy.t_s >= w.deadline_s && !acked) return {ErrorId::PlcAckTimeout};
  if (!w.announced) {
    cy.emit(e);
    w.announced = true;
  }
  return {};
}

}  // namespace nck::kernel
