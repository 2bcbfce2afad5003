#include "channel.hpp"

#include <algorithm>

namespace nck::kernel {

Channel::Channel(const config::Machine& machine, std::size_t index, PlanStore& store,
                 const PlannerOptions& options)
    : planner_(machine, index, store, options),
      number_(static_cast<std::uint8_t>(index + 1)),
      n_axes_(planner_.axis_count()) {}

void Channel::emit(TickOutput& sink, const Event& e) noexcept {
  if (!sink.events.push_back(e)) ++sink.events_dropped;
}

void Channel::finish(EndReason reason, double t_s, TickOutput& sink) noexcept {
  Event e;
  e.t_s = t_s;
  e.channel = number_;
  e.kind = EventKind::end;
  e.end_reason = reason;
  emit(sink, e);
  status_ = reason == EndReason::m30 || reason == EndReason::m2 ? ChannelStatus::ended
                                                                 : ChannelStatus::aborted;
  active_ = false;
  velocity_ = 0;
}

void Channel::start(const Command& c, double t_s, TickOutput& sink) noexcept {
  current_ = c;
  active_ = true;
  Event base;
  base.t_s = t_s;
  base.channel = number_;
  base.file_id = c.file_id;
  base.line = c.line;
  base.has_n = c.has_n;
  base.n = c.n;
  if (c.emit_block_event) {
    Event e = base;
    e.kind = EventKind::block;
    emit(sink, e);
  }
  for (const Command::Warning& w : c.warnings) {
    Event e = base;
    e.kind = EventKind::warning;
    e.id = w.id;
    e.message_index = w.message_index;
    emit(sink, e);
  }
  for (std::uint32_t payload : c.offset_events) {
    Event e = base;
    e.kind = EventKind::offset;
    e.message_index = payload;
    emit(sink, e);
  }
  for (const Output& o : c.outputs) {
    Event e = base;
    e.kind = EventKind::plc_out;
    e.fn = o.fn;
    e.fn_number = o.number;
    e.sync = o.sync;
    emit(sink, e);
  }
  switch (c.kind) {
    case CommandKind::motion:
      profile_.start(c.segment.length(), c.v_cmd_mm_s, c.limits);
      break;
    case CommandKind::dwell:
      dwell_left_s_ = c.dwell_s;
      break;
    case CommandKind::stop: {
      // A dry run has no operator: the stop is reported and the program goes on.
      Event e = base;
      e.kind = EventKind::stop;
      emit(sink, e);
      active_ = false;
      break;
    }
    case CommandKind::end:
      finish(c.end_reason, t_s, sink);
      break;
    case CommandKind::error: {
      Event e = base;
      e.kind = EventKind::error;
      e.id = c.error_id;
      e.message_index = c.message_index;
      emit(sink, e);
      finish(EndReason::error, t_s, sink);
      break;
    }
    case CommandKind::nop:
      active_ = false;
      break;
  }
}

// The set point at path length s: the segment's point, mapped from program
// to machine coordinates when a rotation acts.
void Channel::place(double s_mm) noexcept {
  if (!current_.mapped) {
    current_.segment.point_at(s_mm, pos_);
    return;
  }
  motion::AxisVector pcs = pos_;
  current_.segment.point_at(s_mm, pcs);
  current_.map.apply(pcs, pos_, n_axes_);
}

void Channel::execute(double dt_s, const ChannelInput& in) noexcept {
  if (current_.kind == CommandKind::motion) {
    const double ovr = in.feedhold ? 0.0 : std::clamp(in.feed_override_pct, 0.0, 100.0) / 100.0;
    const motion::ProfileSample st = profile_.step(dt_s, ovr);
    place(st.s_mm);
    velocity_ = st.v_mm_s;
    if (st.finished) {
      place(current_.segment.length());
      velocity_ = 0;
      active_ = false;
    }
  } else if (current_.kind == CommandKind::dwell) {
    dwell_left_s_ -= dt_s;
    // Half a cycle of tolerance so a dwell of k cycles takes exactly k cycles.
    if (dwell_left_s_ <= 0.5 * dt_s) active_ = false;
  }
}

void Channel::tick(double t_s, double dt_s, const ChannelInput& in, ChannelOutput& out,
                   TickOutput& sink) noexcept {
  if (!done()) {
    if (in.reset) {
      finish(EndReason::reset, t_s, sink);
    } else {
      // Blocks without duration (nop, stop) take no cycle of their own.
      while (!active_ && !done() && !queue_.empty()) {
        start(queue_.front(), t_s, sink);
        queue_.pop();
      }
      if (active_) execute(dt_s, in);
      if (!done()) status_ = active_ ? ChannelStatus::running : ChannelStatus::waiting;
    }
  }
  for (std::size_t j = 0; j < n_axes_; ++j) out.axis_mcs[j] = pos_[j];
  out.path_velocity_mm_s = velocity_;
  out.status = status_;
}

}  // namespace nck::kernel
