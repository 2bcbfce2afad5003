#include "channel.hpp"

#include "nck/kernel/braking_reserve.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace nck::kernel {

Channel::Channel(std::size_t index, std::size_t n_axes, const std::vector<std::int8_t>& spindles,
                 CommandQueue& commands, FeedbackQueue& feedback)
    : commands_(&commands),
      feedback_(&feedback),
      number_(static_cast<std::uint8_t>(index + 1)),
      n_axes_(n_axes) {
  for (std::int8_t s : spindles) (void)spindles_.push_back(s);
  manual_share_.fill(1.0);
  manual_share_start_.fill(1.0);
}

Event Channel::event(EventKind k, double t_s) const noexcept {
  Event e;
  e.t_s = t_s;
  e.channel = number_;
  e.kind = k;
  e.file_id = current_.file_id;
  e.line = current_.line;
  e.has_n = current_.has_n;
  e.n = current_.n;
  return e;
}

void Channel::set_state(ProgramState to, StateReason why, double t_s, TickOutput& sink) noexcept {
  if (to == state_) return;
  Event e = event(EventKind::state, t_s);
  e.state_from = static_cast<std::uint8_t>(state_);
  e.state_to = static_cast<std::uint8_t>(to);
  e.state_reason = static_cast<std::uint8_t>(why);
  sink.emit(e);
  state_ = to;
}

namespace {

// The program state a program end leaves, and why.
std::pair<ProgramState, StateReason> state_after(EndReason r) noexcept {
  switch (r) {
    case EndReason::m30: return {ProgramState::ended, StateReason::m30};
    case EndReason::m2: return {ProgramState::ended, StateReason::m2};
    case EndReason::error: return {ProgramState::error, StateReason::error};
    case EndReason::reset: return {ProgramState::idle, StateReason::reset};
    case EndReason::max_time: return {ProgramState::ended, StateReason::max_time};
    case EndReason::max_wall: return {ProgramState::ended, StateReason::max_wall};
    case EndReason::interrupted: return {ProgramState::ended, StateReason::interrupted};
    case EndReason::hold: return {ProgramState::ended, StateReason::hold};
  }
  return {ProgramState::ended, StateReason::m30};
}

}  // namespace

void Channel::end_program(EndReason reason, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept {
  dissolve_links(reason, t_s, sink, ctx);
  const bool ok = reason == EndReason::m30 || reason == EndReason::m2;
  status_ = ok ? ChannelStatus::ended : ChannelStatus::aborted;
  active_ = false;
  velocity_ = 0;
  passing_ = reserve_ = starved_ = false;
  profile_.reset();
  waits_.clear();
  late_.clear();
  end_c_axis(ctx);
  dist_.stop(reason != EndReason::error);  // an error state stays visible
  note_dist_state(t_s, sink);
  release_tap_spindle(ctx);
  take_links(Command{}, ctx);
  // Program end keeps an endless rotation unless the HLI asks to stop it; a
  // reset or an abort stops the channel's spindles (unless P-AXIS-00455).
  for (std::int8_t s : spindles_) {
    if (s < 0 || static_cast<std::size_t>(s) >= ctx.spindle_count) continue;
    SpindleUnit& u = ctx.spindles[s];
    if (u.channel != number_) continue;
    if (reason == EndReason::reset) {
      u.axis.reset();
    } else if (!ok) {
      u.axis.abort();  // an error state stays visible until a reset
    } else if (ctx.spindle_controls && (*ctx.spindle_controls)[static_cast<std::size_t>(s)].stop_at_program_end) {
      (void)u.axis.stop();
    }
  }
  // `end` is the channel's last event (SPEC 2.3): what the end did to its
  // spindles is reported before it, not by the spindles' cycle after it.
  for (std::int8_t s : spindles_)
    if (s >= 0 && static_cast<std::size_t>(s) < ctx.spindle_count && ctx.spindles[s].channel == number_)
      report_spindle_changes(ctx.spindles[s], s, t_s, sink);
  const auto [state, why] = state_after(reason);
  set_state(state, why, t_s, sink);
  Event e = event(EventKind::end, t_s);
  e.end_reason = reason;
  sink.emit(e);
}

void Channel::raise(ErrorId id, std::uint32_t message, double t_s, TickOutput& sink,
                    ChannelContext& ctx) noexcept {
  // The state changes first, so that the error stays right before its end.
  set_state(ProgramState::error, StateReason::error, t_s, sink);
  Event e = event(EventKind::error, t_s);
  e.id = id;
  e.message_index = message;
  sink.emit(e);
  end_program(EndReason::error, t_s, sink, ctx);
}

void Channel::start(const Command& c, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept {
  current_ = c;
  if (state_ == ProgramState::idle) set_state(ProgramState::running, StateReason::start, t_s, sink);
  // Only motions (and blocks without motion in between) continue a path
  // at speed; anything else starts from standstill.
  if (c.kind != CommandKind::motion && c.kind != CommandKind::nop) {
    passing_ = false;
    profile_.reset();
  }
  active_ = true;
  phase_ = Phase::pre_wait;
  if (c.emit_block_event) {
    Event e = event(EventKind::block, t_s);
    e.message_index = c.frame_index;  // the block's program -> machine map (report)
    sink.emit(e);
  }
  for (const Command::Warning& w : c.warnings) {
    Event e = event(EventKind::warning, t_s);
    e.id = w.id;
    e.message_index = w.message_index;
    sink.emit(e);
  }
  for (std::uint32_t payload : c.offset_events) {
    Event e = event(EventKind::offset, t_s);
    e.message_index = payload;
    sink.emit(e);
  }
  if (c.trc_event) {
    Event e = event(EventKind::trc, t_s);
    e.trc_state = c.trc_state;
    e.trc_d = c.trc_d;
    e.trc_radius_mm = c.trc_radius_mm;
    sink.emit(e);
  }
  if (c.kind == CommandKind::error) {
    raise(c.error_id, c.message_index, t_s, sink, ctx);
    return;
  }
  if (!start_c_axis(c, t_s, sink, ctx)) return;
  if (!take_ax_link(c, t_s, sink, ctx)) return;
  if (!take_dist(c, t_s, sink, ctx)) return;
  take_links(c, ctx);
  manual_mask_ = (manual_mask_ | c.manual_on) & ~c.manual_off;
  if (manual_mask_ != 0) handwheel_used_ = true;  // until the first G201 every offset is zero
  if (c.get_manual_offsets) manual_fetch_pending_ = true;
  manual_share_start_ = manual_share_;
  if (c.feed_motion) take_late_waits(SyncPoint::late_motion);
  if (c.expl_syn) take_late_waits(SyncPoint::late_explicit);
  issue_all(SyncPoint::before, t_s, sink, ctx);
}

// The body of the block: motion, dwell, or nothing.
void Channel::execute(double t_s, double dt_s, const ChannelInput& in, TickOutput& sink,
                      ChannelContext& ctx) noexcept {
  if (current_.kind == CommandKind::motion) {
    // A switch counts once this run has moved (not one left from the block before).
    if (current_.measure && (awaiting_probe_ || (in.probe_switched && probe_armed_))) {
      end_measuring_run(t_s, in, sink, ctx);
      return;
    }
    const double ovr = in.feedhold ? 0.0 : std::clamp(in.feed_override_pct, 0.0, 100.0) / 100.0;
    limit_path(ctx);
    keep_braking_reserve(dt_s);
    const motion::ProfileSample st = profile_.step(dt_s, ovr);
    if (reserve_ && st.braking) note_starved(t_s, sink);
    moved_this_cycle_ = st.v_mm_s > 0;
    probe_armed_ = current_.measure;
    place(st.s_mm);
    follow_path(st.s_mm, st.v_mm_s, ctx);
    velocity_ = st.v_mm_s;
    if (!st.finished) return;
    if (!reserve_) starved_ = false;  // the episode ends with a block that ran as planned
    place(current_.segment.length());
    // Continuous path: the block ends at speed and the next one takes over
    // within this cycle (the look-ahead planned nothing to wait for between).
    passing_ = profile_.v() > 0;
    velocity_ = profile_.v();
    // The probe reports a switch one cycle after it happened: a G100 run
    // that reached its end point looks one cycle longer before it ends.
    if (current_.measure) awaiting_probe_ = true;
    else phase_ = Phase::post_wait;
  } else if (current_.kind == CommandKind::dwell && current_.dwell_spindle >= 0) {
    dwell_revolutions(t_s, dt_s, sink, ctx);
  } else if (current_.kind == CommandKind::dwell) {
    dwell_left_s_ -= dt_s;
    // Half a cycle of tolerance so a dwell of k cycles takes exactly k cycles.
    if (dwell_left_s_ <= 0.5 * dt_s) phase_ = Phase::post_wait;
  } else {
    phase_ = Phase::post_wait;
  }
}

// While the commands queued after a motion do not reach a stop or a braking
// distance, its end speed is lowered to what they leave room for; raised
// again, up to the planned speed, as soon as preparation queues more.
void Channel::keep_braking_reserve(double dt_s) noexcept {
  if (!reserve_) return;
  const double v_end = reserve_end_speed(current_, *commands_, dt_s);
  profile_.set_end_velocity(v_end);
  reserve_ = v_end < current_.v_end_mm_s;
}

// The braking reserve slowed the path: preparation fell behind. One
// warning per episode (until a block runs as planned again).
void Channel::note_starved(double t_s, TickOutput& sink) noexcept {
  if (starved_) return;
  starved_ = true;
  Event e = event(EventKind::warning, t_s);
  e.id = ErrorId::KernelPrepStarved;
  e.message_index = kNoMessage;
  sink.emit(e);
}

// G4 S..: the dwell lasts as many revolutions as the spindle really turns
// (its set-point speed each cycle, so override and ramps count). A spindle
// that stands when the dwell begins would never end it: an error.
void Channel::dwell_revolutions(double t_s, double dt_s, TickOutput& sink, ChannelContext& ctx) noexcept {
  const SpindleUnit* u = link_spindle(current_.dwell_spindle, ctx);
  const double rpm = u ? std::fabs(u->axis.status().set_rpm) : 0.0;
  if (rpm <= 0 && dwell_revs_left_ == current_.dwell_revs && current_.dwell_revs > 0) {
    raise(ErrorId::KernelDwellSpindleStopped, kNoMessage, t_s, sink, ctx);
    return;
  }
  dwell_revs_left_ -= rpm / 60.0 * dt_s;
  // Half a cycle of tolerance, as for a dwell in seconds.
  if (dwell_revs_left_ <= 0.5 * rpm / 60.0 * dt_s) phase_ = Phase::post_wait;
}

// G100 ends where the probe switched (the axes stop at the latched point and
// the rest of the path is dropped: measuring type 1) or, without a switch,
// at its end point. Preparation learns the result through the feedback queue.
void Channel::end_measuring_run(double t_s, const ChannelInput& in, TickOutput& sink,
                                ChannelContext& ctx) noexcept {
  Feedback f;
  f.kind = FeedbackKind::measured;
  f.measure.triggered = in.probe_switched && probe_armed_;
  if (f.measure.triggered)
    for (std::size_t j = 0; j < n_axes_; ++j) pos_[j] = in.probe_latched_mcs[j] - manual_in_force_mm_[j];
  f.measure.mcs = pos_;
  velocity_ = 0;
  awaiting_probe_ = false;
  probe_armed_ = false;
  phase_ = Phase::post_wait;
  send_feedback(f, t_s, sink, ctx);
}

// The queue holds more records than can be in flight (queues.hpp); a full
// queue is still reported, never dropped silently.
void Channel::send_feedback(const Feedback& f, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept {
  // Preparation would wait for this record for ever: end the program.
  if (!feedback_->push(f) && !done()) raise(ErrorId::KernelFeedbackOverflow, kNoMessage, t_s, sink, ctx);
}

motion::AxisVector Channel::machine_position() const noexcept {
  motion::AxisVector m = pos_;
  for (std::size_t j = 0; j < n_axes_; ++j) m[j] += manual_in_force_mm_[j];
  if (dist_axis_ >= 0 && static_cast<std::size_t>(dist_axis_) < n_axes_) m[dist_axis_] += dist_.offset_mm();
  return m;
}

// The set point at path length s: the segment's point, mapped from program
// to machine coordinates when a rotation acts, and from Cartesian to
// machine X/C under #FACE / #CYL.
void Channel::place(double s_mm) noexcept {
  const double length = current_.segment.length();
  take_manual_share(length > 0 ? std::clamp(s_mm / length, 0.0, 1.0) : 1.0);
  const bool trafo = current_.trafo.kind != motion::CaxTrafoKind::none;
  if (!current_.mapped && !trafo) {
    current_.segment.point_at(s_mm, pos_);
    return;
  }
  motion::AxisVector pcs = pos_;
  current_.segment.point_at(s_mm, pcs);
  if (!trafo) {
    current_.map.apply(pcs, pos_, n_axes_);
    return;
  }
  motion::AxisVector cart = pcs;
  if (current_.mapped) current_.map.apply(pcs, cart, n_axes_);
  motion::cax_to_machine(current_.trafo, cart, pos_, n_axes_);  // pos_ holds the previous C
}

// After the post waits: the block is done.
void Channel::end_block(double t_s, const ChannelInput& in, TickOutput& sink, ChannelContext& ctx) noexcept {
  // Program end switches distance control off: the block ends once the
  // offset has been travelled out (TURNING_OFF).
  if (current_.kind == CommandKind::end && dist_wind_down()) return;
  active_ = false;
  if (current_.kind == CommandKind::stop) {
    stop_program(in, t_s, sink);
  } else if (current_.kind == CommandKind::end) {
    end_program(current_.end_reason, t_s, sink, ctx);
  }
}

// M1 stops only while the HLI's optional-stop switch is on. The channel
// then holds before its next block until a cycle start (ChannelInput).
void Channel::stop_program(const ChannelInput& in, double t_s, TickOutput& sink) noexcept {
  if (current_.optional_stop && !in.optional_stop) return;
  sink.emit(event(EventKind::stop, t_s));
  set_state(ProgramState::hold, current_.optional_stop ? StateReason::m1 : StateReason::m0, t_s, sink);
}

// Runs the current block's phases as far as this cycle allows.
void Channel::advance(double t_s, double dt_s, const ChannelInput& in, TickOutput& sink,
                      ChannelContext& ctx) noexcept {
  if (phase_ == Phase::pre_wait) {
    for (;;) {
      if (!waits_done(SyncPoint::before, t_s, sink, ctx) || done()) return;
      // Actions held back behind a gear change go out once it is done.
      if (next_action_ >= current_.spindle_actions.size()) break;
      (void)issue_spindle_actions(SyncPoint::before, t_s, sink, ctx);
      if (done()) return;
    }
    phase_ = Phase::body;
    if (current_.kind == CommandKind::motion) {
      const double v_end = reserve_end_speed(current_, *commands_, dt_s);
      reserve_ = v_end < current_.v_end_mm_s;
      profile_.start(current_.segment.length(), current_.v_cmd_mm_s, current_.limits, v_end);
      if (!start_links(t_s, sink, ctx)) return;
      if (passing_) {
        // The block before ran into this one during this cycle: the set
        // point is already the distance it ran past its end.
        passing_ = false;
        place(profile_.s());
        velocity_ = profile_.v();
        return;
      }
      // Right after an exact stop the first step may be gentler
      // (Command::start_a_mm_s2: a sharp turn or a reversal).
      if (moved_last_cycle_) profile_.limit_first_step(current_.start_a_mm_s2);
    }
    if (current_.kind == CommandKind::dwell) dwell_left_s_ = current_.dwell_s;
    dwell_revs_left_ = current_.dwell_revs;
  }
  if (phase_ == Phase::body) {
    const bool timed = current_.kind == CommandKind::motion || current_.kind == CommandKind::dwell;
    execute(t_s, dt_s, in, sink, ctx);
    if (phase_ != Phase::post_wait) return;
    issue_all(SyncPoint::after, t_s, sink, ctx);
    // A motion or dwell used this cycle; its post waits are checked next
    // cycle — unless the path passes on into the next block now.
    if (timed && !passing_) return;
  }
  if (phase_ == Phase::post_wait && waits_done(SyncPoint::after, t_s, sink, ctx) && !done())
    end_block(t_s, in, sink, ctx);
}

void Channel::tick(double t_s, double dt_s, const ChannelInput& in, ChannelOutput& out,
                   TickOutput& sink, ChannelContext& ctx) noexcept {
  moved_last_cycle_ = moved_this_cycle_;
  moved_this_cycle_ = false;
  if (!done()) {
    if (in.reset) {
      end_program(EndReason::reset, t_s, sink, ctx);
    } else {
      for (;;) {
        if (!active_) {
          if (state_ == ProgramState::hold) {
            if (!in.cycle_start) break;
            set_state(ProgramState::running, StateReason::cycle_start, t_s, sink);
          }
          if (commands_->empty()) break;
          start(commands_->front(), t_s, sink, ctx);
          commands_->pop();
          if (done()) break;
        }
        advance(t_s, dt_s, in, sink, ctx);
        // Blocks without duration take no cycle of their own.
        if (active_ || done()) break;
      }
      if (!done()) follow_css(ctx);
      if (!done()) {
        // Running while a block's motion or dwell runs; waiting for a
        // synchronisation or for blocks otherwise.
        status_ = active_ && phase_ == Phase::body ? ChannelStatus::running : ChannelStatus::waiting;
      }
    }
  }
  follow_axis_links();
  follow_c_axis(dt_s, ctx);
  follow_handwheel(t_s, dt_s, in, sink, ctx);
  run_dist(t_s, in, sink, ctx);
  for (std::size_t j = 0; j < n_axes_; ++j) out.axis_mcs[j] = pos_[j] + manual_in_force_mm_[j];
  dist_output(out);
  out.path_velocity_mm_s = velocity_;
  out.status = status_;
  out.program_state = state_;
}

// Handwheel turns move the axes that are in manual mode (G201); the offset
// is travelled at a limited speed (docs/decisions.md). #GET MANUAL OFFSETS
// reports the offsets reached at the end of its cycle.
void Channel::follow_handwheel(double t_s, double dt_s, const ChannelInput& in, TickOutput& sink,
                               ChannelContext& ctx) noexcept {
  // Until the first G201 every handwheel offset is zero: nothing to follow.
  const double step = kHandwheelSpeed_mm_s * dt_s;
  for (std::size_t j = 0; handwheel_used_ && j < n_axes_; ++j) {
    if ((manual_mask_ >> j) & 1u) manual_target_mm_[j] += in.handwheel_mm[j];
    const double d = manual_target_mm_[j] - manual_mm_[j];
    manual_mm_[j] += std::clamp(d, -step, step);
    manual_in_force_mm_[j] = manual_mm_[j] * manual_share_[j];
  }
  if (!manual_fetch_pending_) return;
  manual_fetch_pending_ = false;
  Feedback f;
  f.kind = FeedbackKind::manual_offsets;
  f.manual_offsets_mm = manual_mm_;
  send_feedback(f, t_s, sink, ctx);
}

// A motion block takes the handwheel offset of its axes in or out (command
// manual_offset_axes) in step with its path, `fraction` = 0 at its start and
// 1 at its end, so the set point never jumps by the offset.
void Channel::take_manual_share(double fraction) noexcept {
  for (std::size_t j = 0; j < n_axes_; ++j) {
    const double target = (current_.manual_offset_axes >> j) & 1u ? 1.0 : 0.0;
    manual_share_[j] = manual_share_start_[j] + (target - manual_share_start_[j]) * fraction;
  }
}

}  // namespace nck::kernel
