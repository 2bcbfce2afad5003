#include "path_unit.hpp"

#include "nck/kernel/braking_reserve.hpp"
#include "nck/kernel/hsc_chain.hpp"

namespace nck::kernel {

void PathUnit::start_block(const Command& c, const StartPoint* start, const ProgramMap* map) noexcept {
  const Motion* m = c.as<Motion>();
  if (!m) {
    if (!c.is<Nop>()) {
      passing_ = false;
      profile_.reset();
    }
    return;
  }
  segment_ = motion::Segment::joined(start ? start->pos : segment_.end_point(), m->path);
  if (map) map_ = map->map;
  else map_.reset();
}

void PathUnit::start_motion(const Motion& m, const CommandQueue& queued, double dt_s) noexcept {
  const double v_end = reserve_end_speed(m, queued, dt_s);
  reserve_ = v_end < m.v_end_mm_s;
  HscChain h;
  if (chains(m)) h = hsc_chain(m, segment_.length(), queued, dt_s);
  note_chain(h);
  // Inside a chain this segment's end is passed at the chain's speed; the
  // chain's end is lowered while it reaches the end of the queue.
  if (hsc_chained_) reserve_ = hsc_open_;
  profile_.start(segment_.length(), m.v_cmd_mm_s, m.limits, hsc_chained_ ? m.v_end_mm_s : v_end, h.chain);
  if (m.into_fillet) profile_.pass_into_fillet();
  profile_.brake_through(m.brake_beyond_mm);
}

void PathUnit::note_chain(const HscChain& h) noexcept {
  hsc_chained_ = h.chain.length_mm > 0;
  hsc_open_ = h.open;
  hsc_seen_ = h.queued_seen;
}

bool PathUnit::carry_on(const Motion& m) noexcept {
  if (passing_) {
    passing_ = false;
    if (m.pass_in_limited) profile_.pass_first_step(m.start_a_mm_s2);
    velocity_ = profile_.v();
    return true;
  }
  // Right after an exact stop the first step may be gentler
  // (Motion::start_a_mm_s2: a sharp turn or a reversal).
  if (moved_last_cycle_) profile_.limit_first_step(m.start_a_mm_s2);
  return false;
}

void PathUnit::end_motion() noexcept {
  if (!reserve_) starved_ = false;  // the episode ends with a block that ran as planned
  // Continuous path: the block ends at speed and the next one takes over
  // within this cycle (the look-ahead planned nothing to wait for between).
  passing_ = profile_.v() > 0;
  velocity_ = profile_.v();
}

void PathUnit::place(const Motion& m, double s_mm, std::size_t n_axes) noexcept {
  const bool trafo = m.trafo.kind != motion::CaxTrafoKind::none;
  if (!map_ && !trafo) {
    segment_.point_at(s_mm, pos_);
    return;
  }
  motion::AxisVector pcs = pos_;
  segment_.point_at(s_mm, pcs);
  if (!trafo) {
    map_->apply(pcs, pos_, n_axes);
    return;
  }
  motion::AxisVector cart = pcs;
  if (map_) map_->apply(pcs, cart, n_axes);
  motion::cax_to_machine(m.trafo, cart, pos_, n_axes);  // pos_ holds the previous C
}

bool PathUnit::end_at_standstill(double dt_s) noexcept {
  if (!profile_.stop_fits(dt_s)) return false;
  reserve_ = false;  // the end speed is 0 now; no reserve raises it again
  hsc_chained_ = hsc_open_ = false;  // nor a chain (set_end_velocity(0) ends it in the profile)
  profile_.set_end_velocity(0.0);
  return true;
}

void PathUnit::reset() noexcept {
  velocity_ = 0;
  passing_ = reserve_ = starved_ = out_of_corner_stop_ = false;
  hsc_chained_ = hsc_open_ = false;
  profile_.reset();
  // The next motion starts where the path stands, not at the end of a block
  // a reset left (a rotated block's segment is in program coordinates: kept).
  if (map_) return;
  motion::SegmentTail here = segment_.tail();
  here.kind = motion::SegmentKind::line;
  here.end = pos_;
  here.length_mm = 0;
  segment_ = motion::Segment::joined(pos_, here);
}

// While the commands queued after a motion do not reach a stop or a braking
// distance, its end speed is lowered to what they leave room for; raised
// again, up to the planned speed, as soon as preparation queues more. An
// HSC chain that reaches the end of the queue grows the same way.
void PathUnit::keep_braking_reserve(const Motion& m, const CommandQueue& queued, double dt_s) noexcept {
  if (hsc_open_) {
    if (chain_view(queued) == hsc_seen_) return;  // nothing new within its view: the chain stays
    const bool was_chained = hsc_chained_;
    const HscChain h = hsc_chain(m, segment_.length(), queued, dt_s);  // more queued: it may reach further
    note_chain(h);
    if (was_chained || hsc_chained_) profile_.set_chain(h.chain);
    if (hsc_chained_) {
      reserve_ = hsc_open_;
      return;
    }
    reserve_ = true;  // the motion alone (nothing joins yet): its own reserve below
  }
  if (!reserve_) return;
  const double v_end = reserve_end_speed(m, queued, dt_s);
  profile_.set_end_velocity(v_end);
  reserve_ = v_end < m.v_end_mm_s;
}

// The braking reserve slowed the path: preparation fell behind. One
// warning per episode (until a block runs as planned again).
void PathUnit::note_starved(Cycle& cy) noexcept {
  if (starved_) return;
  starved_ = true;
  cy.emit(ev::Warning{{ErrorId::KernelPrepStarved, {}, {}}});
}

// Time by cause: a few comparisons of what the profile did with what it
// was asked for. A speed-up keeps the cause it began with (from standstill:
// accelerating; out of a corner's reduced speed: corner) until it ends.
CycleCause PathUnit::classify(const Motion& m, const motion::ProfileSample& st, double v_prev, double ovr,
                              const Cycle& cy) noexcept {
  const CycleCause last = cause_;
  const double v = st.v_mm_s;
  const bool rising = v > v_prev;
  if (!rising) ramp_ = CycleCause::none;
  if (cy.resetting) return CycleCause::braking;  // a reset: braking towards its end
  if (cy.stopped) return CycleCause::hold;  // NC stop: the channel holds
  if (cy.in.feedhold) return CycleCause::feedhold;
  if (reserve_ && st.braking) return CycleCause::starved;
  if (!cy.block.feed_motion && !m.measure) return CycleCause::rapid;  // G0 (a G100 run moves at F)
  const double limit = profile_.velocity_limit();
  const double cmd = limit >= 0 ? std::min(m.v_cmd_mm_s, limit) : m.v_cmd_mm_s;
  const double v_max = profile_.limits().v_max_mm_s;
  const double tol = 1e-9 * std::max(1.0, cmd);
  if (profile_.override_ignored()) ovr = 1.0;
  if (st.braking) return profile_.end_velocity() > 0 || m.corner_stop ? CycleCause::corner : CycleCause::braking;
  if (v >= std::min(cmd, v_max) - tol && v > 0) return v_max < cmd - tol ? CycleCause::axis_velocity : CycleCause::feed;
  if (v >= std::min(cmd * ovr, v_max) - tol && v > 0) return CycleCause::override_;
  if (rising) {
    const bool out_of_corner = out_of_corner_stop_ || (last == CycleCause::corner && v_prev > 0);
    if (ramp_ == CycleCause::none) ramp_ = out_of_corner ? CycleCause::corner : CycleCause::accelerating;
    return ramp_;
  }
  // Holding the end speed over the last cycles before passing on.
  const double v_end = profile_.end_velocity();
  if (v_end > 0 && v <= v_end + tol) return CycleCause::corner;
  if (v == 0 && limit == 0) return CycleCause::wait;  // the coupling holds the path (spindle at rest)
  if (v == 0 && out_of_corner_stop_) return CycleCause::corner;  // a cycle at rest in the corner
  return ovr < 1 ? CycleCause::override_ : CycleCause::braking;
}

}  // namespace nck::kernel
