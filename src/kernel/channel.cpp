#include "channel.hpp"

#include <algorithm>
#include <utility>
#include <variant>

namespace nck::kernel {

Channel::Channel(std::size_t index, std::size_t n_axes, const std::vector<std::int8_t>& spindles,
                 CommandQueue& commands, FeedbackQueue& feedback)
    : commands_(&commands),
      feedback_(&feedback),
      number_(static_cast<std::uint8_t>(index + 1)),
      n_axes_(n_axes) {
  for (std::int8_t s : spindles) (void)spindles_.push_back(s);
}

void Channel::tick(double t_s, double dt_s, const ChannelInput& in, ChannelOutput& out,
                   TickOutput& sink, ChannelContext& ctx) noexcept {
  Cycle cy{t_s, dt_s, in, sink, ctx, *feedback_, current_, number_, n_axes_,
           std::span<const std::int8_t>(spindles_.begin(), spindles_.size())};
  path_.begin_cycle();
  hold_.begin_cycle();
  jog_.begin_cycle();
  const bool was_error = state_ == ProgramState::error;  // before this cycle's machine inputs
  follow_machine(cy);
  const ErrorId refused = refusal(cy);  // E-stop or machine off: nothing starts
  if (in.reset) jog_.release_all();
  if (!in.jogs.empty()) take_jogs(cy);
  if (in.cycle_start && refused != ErrorId{}) {
    cy.emit(ev::Warning{{refused, {}, {}}});
  } else if (in.cycle_start && was_error && state_ == ProgramState::error && !in.reset) {
    cy.emit(ev::Warning{{ErrorId::KernelCycleStartInError, {}, {}}});  // an operator action the state does not allow
  }
  if (done() && refused != ErrorId{}) refuse_mdi(refused, cy);
  if (done()) take_mdi(cy);
  if (in.reset && state_ == ProgramState::error && !cy.machine.estop && !amp_latched_) clear_error(cy);
  cause_ = done() ? CycleCause::none : CycleCause::transition;
  if (!done()) follow_stop(cy);
  if (!done()) follow_drives(cy);
  if (!done()) follow_reset(cy);
  if (!done()) {
    run_blocks(cy);
    if (!done()) spindle_path_.follow_css(path_.position(), handwheel_.in_force_mm(), ctx);
    if (!done()) {
      // Running while a block's motion or dwell runs; waiting for a
      // synchronisation or for blocks otherwise.
      status_ = active_ && phase_ == Phase::body ? ChannelStatus::running : ChannelStatus::waiting;
    }
  }
  if (jog_.moving()) move_jogged(cy);
  if (search_.active() || search_.moving()) step_homing_search(cy);
  ax_links_.follow(path_.position());
  cax_.follow(dt_s, path_.position(), ctx);
  (void)fail(handwheel_.follow(cy, in.manual_mode && refused == ErrorId{} ? manual_axes(in) : 0u), cy);
  (void)fail(technologies_.follow(path_.position(), done(), cy), cy);
  write_output(out, ctx);
}

// Starts and advances blocks as far as this cycle allows.
void Channel::run_blocks(Cycle& cy) noexcept {
  for (;;) {
    if (!active_) {
      if (resetting_ && !continues_braking()) {
        end_program(reset_reason(), cy);
        break;
      }
      if (!resetting_ && refusal(cy) != ErrorId{}) {
        cause_ = CycleCause::hold;  // E-stop or machine off: no block starts
        break;
      }
      if (state_ == ProgramState::hold) {
        if (manual_blocks_program(cy.in) || !hold_.released(cy.in)) {
          cause_ = CycleCause::hold;
          break;
        }
        set_state(ProgramState::running, StateReason::cycle_start, cy);
      }
      if (commands_->empty()) {
        cause_ = CycleCause::starved;  // preparation has not queued the next block
        break;
      }
      if (drives_hold(cy)) break;
      if (search_.moving()) break;  // a homing search cut short still brakes
      if (state_ == ProgramState::idle && manual_blocks_program(cy.in)) {
        cause_ = CycleCause::hold;  // manual mode keeps the program from starting
        break;
      }
      start(cy);
      commands_->pop();
      if (done()) break;
    }
    advance(cy);
    // Blocks without duration take no cycle of their own.
    if (active_ || done()) break;
  }
}

void Channel::write_output(ChannelOutput& out, const ChannelContext& ctx) const noexcept {
  const motion::AxisVector& pos = path_.position();
  const motion::AxisVector& manual = handwheel_.in_force_mm();
  for (std::size_t j = 0; j < n_axes_; ++j) out.axis_mcs[j] = pos[j] + manual[j];
  technologies_.output(out, n_axes_);
  out.path_velocity_mm_s = path_.velocity_mm_s();
  out.status = status_;
  out.program_state = state_;
  out.cause = cause_;
  const Motion* m = active_ ? current_.as<Motion>() : nullptr;
  out.feed_mm_s = m ? spindle_path_.commanded_feed_mm_s(m->v_cmd_mm_s, ctx) : 0.0;
  out.distance_to_go_mm = m ? std::max(0.0, path_.segment().length() - path_.s_mm()) : 0.0;
  const motion::AxisVector& end = m ? path_.segment().end_point() : pos;
  for (std::size_t j = 0; j < n_axes_; ++j) out.axis_dtg[j] = end[j] - pos[j];
  out.wait_reason = wait_reason_;
  out.homed_axes = homing_.homed();
  out.homing_required = homing_.required();
  out.axis_drive_offset = search_.drive_offsets();
  out.drive_homing_axes = search_.drive_homing();
}

motion::AxisVector Channel::machine_position() const noexcept {
  motion::AxisVector m = path_.position();
  const motion::AxisVector& manual = handwheel_.in_force_mm();
  for (std::size_t j = 0; j < n_axes_; ++j) m[j] += manual[j];
  technologies_.add_offset(m, n_axes_);
  return m;
}

namespace {

// What a block's attachments give the units when it starts: pointers into
// the command queue, valid while the command is its front (start()).
struct BlockAttachments {
  const StartPoint* start = nullptr;
  const ProgramMap* map = nullptr;
  const CaxChange* cax = nullptr;
  const LinkCommand* link = nullptr;
  const FeedLink* feed = nullptr;
  const CssLink* css = nullptr;
  const ManualChange* manual = nullptr;
  const HomeAxes* home = nullptr;
};

// Sorts a block's attachments: what is reported goes out as an event (after
// the block event, in queue order), outputs and spindle actions go to the
// sync unit, the rest is noted for the units that take it.
struct AttachmentSorter {
  BlockAttachments& parts;
  SyncUnit& sync;
  ChannelTechnologies& technologies;
  Cycle& cy;

  void operator()(const Warning& w) const noexcept { cy.emit(w); }
  void operator()(const OffsetEvent& o) const noexcept { cy.emit(o); }
  void operator()(const TrcChange& t) const noexcept { cy.emit(t); }
  void operator()(const Output& o) const noexcept { sync.take(o); }
  void operator()(const SpindleAction& a) const noexcept { sync.take(a); }
  void operator()(const StartPoint& x) const noexcept { parts.start = &x; }
  void operator()(const ProgramMap& x) const noexcept { parts.map = &x; }
  void operator()(const CaxChange& x) const noexcept { parts.cax = &x; }
  void operator()(const LinkCommand& x) const noexcept { parts.link = &x; }
  void operator()(const FeedLink& x) const noexcept { parts.feed = &x; }
  void operator()(const CssLink& x) const noexcept { parts.css = &x; }
  void operator()(const ManualChange& x) const noexcept { parts.manual = &x; }
  void operator()(const HomeAxes& x) const noexcept { parts.home = &x; }
  template <class A>
    requires ChannelTechnologies::takes<A>
  void operator()(const A& x) const noexcept { technologies.note(x); }
};

}  // namespace

// The queue's front command starts (it leaves the queue after this).
void Channel::start(Cycle& cy) noexcept {
  current_ = commands_->front();
  enter_restart_state(cy);
  active_ = true;
  phase_ = Phase::pre_wait;
  if (current_.emit_block_event) {
    cy.emit(ev::Block{current_.frame_index});  // with the block's program -> machine map (report)
  }
  BlockAttachments parts;
  sync_.start_block(current_);
  technologies_.begin_block();
  const AttachmentSorter sort{parts, sync_, technologies_, cy};
  for (std::size_t i = 0; i < current_.attachments; ++i) std::visit(sort, commands_->attachment(i));
  path_.start_block(current_, parts.start, parts.map);
  hold_.start_block(current_, cy.in.stop_at);
  if (const Error* e = current_.as<Error>()) {
    raise(e->id, e->message, cy);
    return;
  }
  // P-AXIS-00277: an unhomed axis refuses the motion before it moves.
  if (const auto e = homing_.start(current_, parts.home, path_.segment(), parts.map ? &parts.map->map : nullptr)) {
    raise(e->id, e->message, cy);
    return;
  }
  if (refuse_into_switch(cy)) return;  // a limit switch is on where it goes
  begin_homing_search(parts.home, cy);
  // Each unit takes its part of the block; a fault ends the program.
  if (parts.cax && fail(cax_.start(*parts.cax, path_.position(), cy), cy)) return;
  if (parts.link && fail(ax_links_.start(*parts.link, path_.position(), cy), cy)) return;
  if (fail(technologies_.start(cy), cy)) return;
  spindle_path_.start(parts.feed, parts.css, cy.machine);
  handwheel_.start(parts.manual);
  (void)fail(sync_.issue_all(SyncPoint::before, cy), cy);
}

// Runs the current block's phases as far as this cycle allows.
void Channel::advance(Cycle& cy) noexcept {
  if (phase_ == Phase::pre_wait && !begin_body(cy)) return;
  if (phase_ == Phase::body) {
    const bool timed = current_.is<Motion>() || current_.is<Dwell>();
    execute(cy);
    if (phase_ != Phase::post_wait) return;
    (void)fail(sync_.issue_all(SyncPoint::after, cy), cy);
    // A motion or dwell used this cycle; its post waits are checked next
    // cycle — unless the path passes on into the next block now.
    if (timed && !path_.passing()) return;
  }
  if (phase_ == Phase::post_wait && waits_done(SyncPoint::after, cy) && !done()) end_block(cy);
}

// Once the waits before the body are over: the body begins. False when
// nothing more happens in this cycle.
bool Channel::begin_body(Cycle& cy) noexcept {
  for (;;) {
    if (!waits_done(SyncPoint::before, cy) || done()) return false;
    // Actions held back behind a gear change go out once it is done.
    if (!sync_.actions_left()) break;
    (void)fail(sync_.issue_spindle_actions(SyncPoint::before, cy), cy);
    if (done()) return false;
  }
  if (search_.active()) {  // G74 on a real drive: its motion waits for the reference
    cause_ = CycleCause::wait;
    wait_reason_ = WaitReason::homing;
    return false;
  }
  phase_ = Phase::body;
  if (const Motion* m = current_.as<Motion>()) {
    path_.start_motion(*m, *commands_, cy.dt_s);
    if (fail(spindle_path_.start_motion(path_.profile(), cy.machine), cy)) return false;
    if (path_.carry_on(*m)) {
      // The block before ran into this one during this cycle: the set
      // point is already the distance it ran past its end.
      place(*m, path_.s_mm());
      return false;
    }
  }
  if (const Dwell* d = current_.as<Dwell>()) dwell_.start(*d);
  return true;
}

// The body of the block: motion, dwell, or nothing.
void Channel::execute(Cycle& cy) noexcept {
  if (const Motion* m = current_.as<Motion>()) {
    run_motion(*m, cy);
  } else if (const Dwell* d = current_.as<Dwell>()) {
    bool over = false;
    cause_ = CycleCause::wait;
    wait_reason_ = WaitReason::dwell;
    if (!fail(dwell_.step(*d, cy, over), cy) && over) phase_ = Phase::post_wait;
  } else {
    phase_ = Phase::post_wait;
  }
}

void Channel::run_motion(const Motion& m, Cycle& cy) noexcept {
  if (measuring_.run_ends(m, cy.in)) {
    const Fault f = measuring_.end_run(path_.position(), handwheel_.in_force_mm(), cy);
    path_.halt();
    phase_ = Phase::post_wait;
    (void)fail(f, cy);
    return;
  }
  spindle_path_.limit_path(path_.profile(), cy.machine);
  spindle_path_.announce_wait(cy);
  hold_.follow(current_, cy.in, sync_.has_functions(), path_, cy.dt_s);
  const motion::ProfileSample st = path_.step(m, *commands_, cy);
  cause_ = path_.cause();
  if (cause_ == CycleCause::wait)
    wait_reason_ = spindle_path_.waits_for_zero_mark() ? WaitReason::zero_mark : WaitReason::coupling;
  measuring_.stepped(m);
  place(m, st.s_mm);
  spindle_path_.follow_path(st.s_mm, st.v_mm_s, cy.machine);
  if (!st.finished) return;
  place(m, path_.segment().length());
  path_.end_motion();
  if (!measuring_.reached_end(m)) phase_ = Phase::post_wait;
}

// The set point at path length s: the path's point and the handwheel
// offset's share in it.
void Channel::place(const Motion& m, double s_mm) noexcept {
  handwheel_.blend(m, path_.segment().length(), s_mm, n_axes_);
  path_.place(m, s_mm, n_axes_);
}

bool Channel::waits_done(SyncPoint phase, Cycle& cy) noexcept {
  if (fail(sync_.update_waits(phase, cy), cy)) return false;
  if (!sync_.waiting(phase)) return true;
  cause_ = CycleCause::wait;
  wait_reason_ = sync_.reason(phase);
  return false;
}

// After the post waits: the block is done.
void Channel::end_block(Cycle& cy) noexcept {
  // Program end switches the technologies off (distance control): the block
  // ends once their offsets have been travelled out (TURNING_OFF).
  const End* end = current_.as<End>();
  if (end && technologies_.wind_down()) return;
  active_ = false;
  homing_.end_block();  // a G74 has reached its home position
  if (current_.mdi == Mdi::end) {
    finish_mdi(cy);
  } else if (current_.restart != Restart::none) {
    leave_restart_state(cy);
  } else if (const Hold* hold = current_.as<Hold>()) {
    stop_program(*hold, cy);
  } else if (end) {
    end_program(end->reason, cy);
  } else if (const auto why = hold_.at_block_end(current_, cy.in, sync_.has_functions(), !path_.passing())) {
    set_state(ProgramState::hold, *why, cy);  // single step, stop at: the next block waits for cycle start
  }
}

// M1 stops only while the HLI's optional-stop switch is on. The channel
// then holds before its next block until a cycle start (ChannelInput).
void Channel::stop_program(const Hold& hold, Cycle& cy) noexcept {
  if (hold.optional_stop && !cy.in.optional_stop) return;
  cy.emit(ev::Stop{});
  set_state(ProgramState::hold, hold.optional_stop ? StateReason::m1 : StateReason::m0, cy);
}

// A channel that is done (program end, reset, MDI done or failed) takes
// the operator's MDI text; what is left of a failed one is dropped, and of
// a program a reset or an error ended, and every MDI command planned before
// preparation knew where that end left the path. rt
void Channel::take_mdi(Cycle& cy) noexcept {
  bool discarded = false;
  while (!commands_->empty() &&
         (commands_->front().mdi == Mdi::none || commands_->front().stops_taken != stops_sent_)) {
    discarded = discarded || commands_->front().mdi != Mdi::none;
    commands_->pop();
  }
  if (discarded && discard_reported_ != stops_sent_) {
    discard_reported_ = stops_sent_;
    cy.emit(ev::Warning{{ErrorId::KernelMdiDiscarded, {}, {}}});
  }
  while (dropping_mdi_ && !commands_->empty()) {
    dropping_mdi_ = commands_->front().mdi != Mdi::end;
    commands_->pop();
  }
  if (!dropping_mdi_ && !commands_->empty() && commands_->front().mdi != Mdi::none) status_ = ChannelStatus::waiting;
}

// NC stop: the path stops as with feedhold and the channel holds, mid-block
// too, until cycle start. rt
void Channel::follow_stop(Cycle& cy) noexcept {
  if (cy.in.stop && !stopped_ && state_ == ProgramState::running) {
    stopped_ = true;
    set_state(ProgramState::hold, StateReason::stop, cy);
  } else if (stopped_ && hold_.released(cy.in)) {
    stopped_ = false;
    set_state(ProgramState::running, StateReason::cycle_start, cy);
  }
  cy.stopped = stopped_;
}

// A reset brakes the path along its path with the deceleration in force,
// as a feedhold does, and ends the program once the path stands. The
// spindles brake with their own ramps from the reset on (a thread's path
// follows its spindle down); a spindle tracking a tap follows the path and
// stops with it, so the tap is never torn. rt
void Channel::follow_reset(Cycle& cy) noexcept {
  if (cy.in.reset && !resetting_) {
    resetting_ = true;
    end_spindles(EndReason::reset, cy, spindle_path_.tap_spindle());
  }
  // A thread's path is not braked on its own: it follows its spindle down.
  cy.resetting = resetting_ && !spindle_path_.threading();
  if (resetting_ && !path_.moving() && !search_.moving()) end_program(reset_reason(), cy);
}

// A drive's error (its ID names the axis) brakes the path within its
// limits as a reset does; at standstill the program ends in error.
void Channel::follow_drives(Cycle& cy) noexcept {
  const DriveReport& r = cy.machine.drives;
  if (r.axis < 0 || drive_failed_) return;
  drive_failed_ = true;
  set_state(ProgramState::error, StateReason::error, cy);
  ev::Error e{{r.error, {}, {}}};
  e.axis = r.axis;
  cy.emit(e);
  if (!resetting_) {
    resetting_ = true;
    end_spindles(EndReason::error, cy, spindle_path_.tap_spindle());
  }
}

// Before a block starts: the program waits until every CiA 402 drive is
// in operation enabled (wait / wait_end events, reason drive_enable).
bool Channel::drives_hold(Cycle& cy) noexcept {
  const bool hold = !cy.machine.drives.ready && !resetting_;
  if (hold != drive_wait_) {
    drive_wait_ = hold;
    const ev::Wait e{WaitReason::drive_enable, std::nullopt};
    if (hold) cy.emit(e);
    else cy.emit(ev::WaitEnd{e});
  }
  if (hold) {
    cause_ = CycleCause::wait;
    wait_reason_ = WaitReason::drive_enable;
  }
  return hold;
}

// Between blocks while a reset brakes: the path still moving runs on into
// the next motion (a transparent block passes as always).
bool Channel::continues_braking() const noexcept {
  if (!path_.moving() || commands_->empty()) return false;
  const Command& next = commands_->front();
  return next.is<Motion>() || next.is<Nop>();
}

// A reset after an error: the channel is idle again, ready for MDI or a
// start, and its spindles leave their error states. rt
void Channel::clear_error(Cycle& cy) noexcept {
  end_spindles(EndReason::reset, cy);
  set_state(ProgramState::idle, StateReason::reset, cy);
}

// MDI is done: the channel is idle again, ready for more.
void Channel::finish_mdi(Cycle& cy) noexcept {
  set_state(ProgramState::idle, StateReason::mdi, cy);
  status_ = ChannelStatus::ended;
}

// An error in MDI ends its text, not the channel: the error is reported,
// the rest of the text dropped, the channel idle and usable.
void Channel::fail_mdi(Cycle& cy) noexcept {
  active_ = false;
  path_.reset();
  homing_.reset();
  search_.abort();
  hold_.reset();
  sync_.clear();
  dropping_mdi_ = true;
  resetting_ = drive_failed_ = false;  // the braking that ended it is over
  // An E-stop leaves the channel in error until its reset, MDI or not.
  set_state(machine_error() ? ProgramState::error : ProgramState::idle, StateReason::error, cy);
  status_ = ChannelStatus::ended;
}

// A command starts: the program state it begins (block search: searching,
// then returning to the contour; MDI: running).
void Channel::enter_restart_state(Cycle& cy) noexcept {
  if (current_.mdi == Mdi::block && state_ != ProgramState::running) {
    set_state(ProgramState::running, StateReason::mdi, cy);
    return;
  }
  switch (current_.restart) {
    case Restart::search_begins: set_state(ProgramState::searching, StateReason::block_search, cy); break;
    case Restart::returns:
    case Restart::returns_no_hold: set_state(ProgramState::returning, StateReason::block_search, cy); break;
    case Restart::none:
      if (state_ == ProgramState::idle) set_state(ProgramState::running, StateReason::start, cy);
      break;
  }
}

// After the return to the contour the channel holds for cycle start (HLI:
// unless no_hold_at_restart); the restart's other commands hold nowhere.
void Channel::leave_restart_state(Cycle& cy) noexcept {
  if (current_.restart == Restart::returns) set_state(ProgramState::hold, StateReason::block_search, cy);
  else if (current_.restart == Restart::returns_no_hold) set_state(ProgramState::running, StateReason::block_search, cy);
}

void Channel::set_state(ProgramState to, StateReason why, Cycle& cy) noexcept {
  if (to == state_) return;
  cy.emit(ev::State{state_, to, why});
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
    case EndReason::stop_at: return {ProgramState::ended, StateReason::stop_at};
    case EndReason::max_trace: return {ProgramState::ended, StateReason::max_trace};
    case EndReason::max_events: return {ProgramState::ended, StateReason::max_events};
  }
  return {ProgramState::ended, StateReason::m30};
}

}  // namespace

void Channel::end_program(EndReason reason, Cycle& cy) noexcept {
  if (reason == EndReason::error && current_.mdi == Mdi::block && active_) {
    fail_mdi(cy);
    return;
  }
  ax_links_.end(reason, cy);
  stopped_ = resetting_ = drive_failed_ = false;
  if (drive_wait_) {
    drive_wait_ = false;
    cy.emit(ev::WaitEnd{ev::Wait{WaitReason::drive_enable, std::nullopt}});
  }
  const bool ok = reason == EndReason::m30 || reason == EndReason::m2;
  status_ = ok ? ChannelStatus::ended : ChannelStatus::aborted;
  active_ = false;
  path_.reset();
  homing_.reset();
  search_.abort();
  if (!ok) {  // preparation may be ahead: it learns where the path stands (MDI plans from there)
    Feedback f;
    f.kind = FeedbackKind::stopped;
    f.path_mcs_mm = path_.position();
    // full: a record still waits, and preparation drops the program anyway
    if (!cy.send(f).any()) ++stops_sent_;
  }
  hold_.reset();
  sync_.clear();
  cax_.end(cy.machine);
  technologies_.end(reason, cy);
  spindle_path_.end(cy.machine);
  end_spindles(reason, cy);
  const auto [state, why] = state_after(reason);
  set_state(state, why, cy);
  cy.emit(ev::End{reason});
}

// Program end keeps an endless rotation unless the HLI asks to stop it; a
// reset or an abort stops the channel's spindles (unless P-AXIS-00455).
void Channel::end_spindles(EndReason reason, Cycle& cy, std::int8_t keep) noexcept {
  const bool ok = reason == EndReason::m30 || reason == EndReason::m2;
  const ChannelContext& ctx = cy.machine;
  for (std::int8_t s : spindles_) {
    if (s < 0 || static_cast<std::size_t>(s) >= ctx.spindle_count) continue;
    SpindleUnit& u = ctx.spindles[s];
    if (u.channel != number_ || s == keep) continue;
    if (reason == EndReason::reset) {
      u.axis.reset();
    } else if (!ok) {
      u.axis.abort();  // an error state stays visible until a reset
    } else if (ctx.spindle_controls && (*ctx.spindle_controls)[static_cast<std::size_t>(s)].stop_at_program_end) {
      (void)u.axis.stop();
    }
  }
  // `end` is the channel's last event (docs/outputs.md): what the end did to its
  // spindles is reported before it, not by the spindles' cycle after it.
  for (std::int8_t s : spindles_)
    if (s >= 0 && static_cast<std::size_t>(s) < ctx.spindle_count && ctx.spindles[s].channel == number_)
      report_spindle_changes(ctx.spindles[s], s, cy.t_s, cy.sink);
}

bool Channel::fail(const Fault& f, Cycle& cy) noexcept {
  if (!f.any()) return false;
  if (done()) return true;
  if (f.reported) end_program(EndReason::error, cy);  // the unit emitted the error event
  else raise(f.id, std::nullopt, cy);
  return true;
}

void Channel::raise(ErrorId id, std::optional<std::uint32_t> message, Cycle& cy, std::optional<std::int8_t> axis) noexcept {
  // The state changes first, so that the error stays right before its end.
  set_state(ProgramState::error, StateReason::error, cy);
  ev::Error e{{id, message, {}}};
  e.axis = axis;
  cy.emit(e);
  end_program(EndReason::error, cy);
}

}  // namespace nck::kernel
