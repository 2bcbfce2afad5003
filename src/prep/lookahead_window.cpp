#include "nck/prep/lookahead_window.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "nck/motion/chord_smoothing.hpp"
#include "nck/motion/corner_blend.hpp"
#include "nck/prep/blend_limits.hpp"
#include "nck/motion/junction.hpp"

namespace nck::prep {
namespace {

using kernel::SyncPoint;

// The block before a fillet reaches the fillet's speed in the crossing
// cycle if that costs it no more than 20 % of its braking (the common
// program: 1 % on its time at PATH_DEV 0.01, docs/performance.md).
constexpr double kIntoFilletShare = 0.8;

// Nothing around it makes the channel wait or act at a block boundary: no
// output, spindle function, probing, manual mode or feedback. Only then can
// the path run through its ends.
bool is_quiet(const PlannedCommand& c) {
  return !c.has<kernel::Output>() && !c.has<kernel::SpindleAction>() && !c.has<kernel::ManualChange>() &&
         !c.measure && !c.head.expl_syn;
}

// A block without motion the path may run through (it only writes events).
bool is_transparent(const PlannedCommand& c) { return c.kind == CommandKind::nop && is_quiet(c); }

// An MVS_SLM function: the channel waits for it when the next G1/G2/G3 starts.
bool waits_at_next_feed_motion(const PlannedCommand& c) {
  bool late = false;
  c.each<kernel::Output>([&](const kernel::Output& o) { late = late || kernel::sync_point(o.sync) == SyncPoint::late_motion; });
  c.each<kernel::SpindleAction>([&](const kernel::SpindleAction& a) { late = late || a.sync == SyncPoint::late_motion; });
  return late;
}

// A blend made smaller for the feed keeps this much speed in hand.
constexpr double kFeedMargin = 1.02;
// ... and takes at least this many cycles at the feed (every piece of a
// blended corner must take more than two: LookAheadWindow::blend).
constexpr double kMinBlendCycles = 3;
// Blocks without motion between two motions that may still be blended.
constexpr std::size_t kMaxLiftedBlocks = 4;
// What a blend leaves of each block it trims, in cycles of its travel.
constexpr double kKeepCycles = 2.5;

// The blend make(share) builds at a share of its largest size, as small as
// still lets the path pass at feed_mm_s (a blend's speed grows with the
// square root of its size under STEP, with the 2/3 power under the jerk
// rule: the 1.5th power of the speed ratio is enough for both, and the
// result is checked): it deviates less and leaves its blocks room for
// their other corners. The largest where no smaller one is as fast.
// `limits`: the returned blend's, from limits_of(its segment).
template <class Make, class LimitsOf>
std::optional<motion::CornerBlend> sized_for_feed(Make make, LimitsOf limits_of, double feed_mm_s, double cycle_s,
                                                  motion::PathLimits& limits) {
  auto largest = make(1.0);
  if (!largest) return largest;
  limits = limits_of(largest->corner);
  const double v_largest = limits.v_max_mm_s;
  if (!(v_largest > kFeedMargin * feed_mm_s)) return largest;
  const double share = std::max(std::pow(kFeedMargin * feed_mm_s / v_largest, 1.5),
                                kMinBlendCycles * cycle_s * feed_mm_s / largest->corner.length());
  if (share >= 0.9) return largest;
  auto sized = make(share);
  if (!sized) return largest;
  const motion::PathLimits l = limits_of(sized->corner);
  if (l.v_max_mm_s < feed_mm_s) return largest;
  limits = l;
  return sized;
}

// Under a jerk-limited slope the acceleration across the path steps by
// v^2 |dk| within a cycle where a fillet meets a block (it is tangent to
// them, not curvature-continuous): dk the change of the curvature vector
// there, 1/r beside a line, more or less beside an arc that turns the
// other or the same way. Like a kink's velocity step (the kink rule,
// CornerUnit), that step stays within what the slope's jerk allows in a
// cycle, a / tr * dt, on each plane axis (TF5200 P-AXIS-00154
// r_trans_weight at its 100 %): v <= sqrt(a / tr * dt / |dk|).
double curvature_step_speed(const motion::Segment& fillet, const motion::AxisVector& k_before,
                            const motion::AxisVector& k_after, const BlendDynamics& d, double cycle_s) {
  const motion::AxisVector k_start = motion::end_curvature(fillet, false), k_end = motion::end_curvature(fillet, true);
  double start_sq = 0, end_sq = 0;
  for (std::size_t j = 0; j < fillet.axis_count(); ++j) {
    start_sq += (k_start[j] - k_before[j]) * (k_start[j] - k_before[j]);
    end_sq += (k_end[j] - k_after[j]) * (k_end[j] - k_after[j]);
  }
  const double bend_sq = std::max(start_sq, end_sq);
  double step_mm_s2 = std::numeric_limits<double>::infinity();
  for (const std::size_t j : {fillet.plane_a(), fillet.plane_b()}) {
    if (j >= d.feed.size()) continue;
    const motion::AxisDynamics& ax = d.feed[j];
    const double tr_s = std::max({ax.tr.acc_up_s, ax.tr.acc_down_s, ax.tr.dec_up_s, ax.tr.dec_down_s});
    if (tr_s > 0) step_mm_s2 = std::min(step_mm_s2, std::min(ax.a_acc_mm_s2, ax.a_dec_mm_s2) / tr_s * cycle_s);
  }
  if (!std::isfinite(step_mm_s2) || !(bend_sq > 0)) return std::numeric_limits<double>::infinity();
  return std::sqrt(step_mm_s2 / std::sqrt(bend_sq));
}

}  // namespace

LookAheadWindow::LookAheadWindow(std::size_t depth, double cycle_s)
    : ring_(depth + 4 * kernel::kMaxCommandsPerBlock), depth_(depth), cycle_s_(cycle_s) {}

bool LookAheadWindow::push(const PlannedBlock& b) {
  if (!has_room()) return false;
  for (const PlannedCommand& c : b) append(c);
  return true;
}

void LookAheadWindow::append(const PlannedCommand& command) {
  const bool must_wait = late_wait_pending_ && command.head.feed_motion;
  const bool linkable = command.kind == CommandKind::motion && open_motion_ != 0 && open_motion_ - 1 >= head_ &&
                        is_quiet(command) && !must_wait;
  // A fillet goes in first (it chains after the motion before and becomes
  // the open motion that c chains after); it also links a corner so sharp
  // that the velocity look-ahead stops there (entry limit 0). Only then is
  // the command copied (3.4 KB) to be changed.
  if (linkable && at(open_motion_ - 1).command.blend_dev_mm > 0 && tail_ - open_motion_ <= kMaxLiftedBlocks) {
    PlannedCommand c = command;
    blend_across(c);
    store(c, linkable);
  } else {
    store(command, linkable);
  }
}

// Blends the corner between the open motion and c. Blocks without motion
// between them (an F word alone, a comment's block, an assignment: CAM
// posts write one before every move) do not stop it: they are lifted out
// and put back after the fillet, whose end is where they then take effect.
void LookAheadWindow::blend_across(PlannedCommand& c) {
  FixedVector<PlannedCommand, kMaxLiftedBlocks> lifted;
  for (std::uint64_t seq = open_motion_; seq < tail_; ++seq) (void)lifted.push_back(at(seq).command);
  const std::uint64_t tail = tail_;
  tail_ = open_motion_;
  if (!blend(open_motion_ - 1, c)) {
    tail_ = tail;  // nothing changed: they stay where they were
    return;
  }
  for (const PlannedCommand& n : lifted) store(n, false);
}

// Command c (as blended) enters the window.
void LookAheadWindow::store(const PlannedCommand& c, bool linkable) {
  const bool chained = linkable && c.v_entry_max_mm_s > 0;
  const std::uint64_t seq = tail_++;
  Entry& e = at(seq);
  e.command = c;
  e.command.v_end_mm_s = 0;
  e.chord_limits = c.limits;
  if (c.kind == CommandKind::motion && next_chord_limits_) e.chord_limits = *std::exchange(next_chord_limits_, std::nullopt);
  e.prev_motion = 0;
  e.end_cap_mm_s = e.through_cap_mm_s = 0;
  e.stairs = Staircase{};
  if (c.kind == CommandKind::motion) {
    const std::uint64_t open = open_motion_;
    open_motion_ = is_quiet(c) && !c.exact_stop ? seq + 1 : 0;
    if (chained) {
      at(open - 1).end_cap_mm_s = c.v_entry_max_mm_s;
      at(open - 1).through_cap_mm_s = c.v_entry_through_max_mm_s;
      e.prev_motion = open;
      raise_chain(seq);
    } else if (linkable) {
      at(open - 1).command.corner_stop = true;  // only the corner stops the path there
    }
  } else if (!is_transparent(c)) {
    open_motion_ = 0;
  }
  if (c.head.feed_motion) late_wait_pending_ = false;  // taken when this block starts
  if (waits_at_next_feed_motion(c)) late_wait_pending_ = true;
}

// The last motion `seq` joined the chain (or changed): the motions before it
// may now end faster, as far as it can still brake from them, and brake
// across their ends where that is faster (braking_staircase.hpp).
void LookAheadWindow::raise_chain(std::uint64_t seq) {
  settle(seq, nullptr);
  for (;;) {
    const Entry& n = at(seq);
    if (n.prev_motion == 0 || n.prev_motion - 1 < head_) return;  // none, or it has left
    const std::uint64_t m = n.prev_motion - 1;
    Entry& e = at(m);
    const Staircase was = e.stairs;
    e.command.v_end_mm_s = std::min(e.end_cap_mm_s, n.stairs.entry_mm_s);
    settle(m, &n.stairs);
    if (e.stairs == was) return;  // nothing changes further back
    seq = m;
  }
}

// A motion that a released one brakes across into keeps braking across,
// along a staircase nowhere lower than the one it had (the released one
// follows that): a new one only where it covers the old.
void LookAheadWindow::settle(std::uint64_t seq, const Staircase* next) {
  Entry& e = at(seq);
  const Staircase s = prep::settle(e.command, seq, e.caps(), next, cycle_s_);
  const bool kept = seq < fixed_end_ && e.stairs.through;
  if (!kept || (s.through && s.covers(e.stairs))) e.stairs = s;
}

// Under a jerk-limited slope a fillet also keeps the contour's jerk within
// what path_limits allows an arc (motion/limits.hpp): the lower speed and
// tangential acceleration of the two, the ramp times of the blocks.
motion::PathLimits LookAheadWindow::jerk_fillet_limits(const motion::Segment& fillet, const BlendDynamics& d,
                                                       const motion::PathLimits& before, double feed_mm_s) {
  motion::PathLimits l = fillet_limits(fillet, d, feed_mm_s);
  if (!jerk_limited(before.slope)) return l;
  const motion::PathLimits arc = motion::path_limits(fillet, d.feed, before.slope);
  l.v_max_mm_s = std::min(l.v_max_mm_s, arc.v_max_mm_s);
  l.a_acc_mm_s2 = std::min(l.a_acc_mm_s2, arc.a_acc_mm_s2);
  l.a_dec_mm_s2 = std::min(l.a_dec_mm_s2, arc.a_dec_mm_s2);
  l.slope = before.slope;
  l.tr = motion::longest(before.tr, arc.tr);
  return l;
}

// Whether replacing the command at `seq` by one whose staircase is
// `changed` keeps every released command able to brake: follows the lowered
// staircases back along the chain (settled as raise_chain would) until they
// are no lower (the normal case: at once), and fails when they would reach
// a command that has left the window (or one that such a command brakes
// across into).
bool LookAheadWindow::lowering_is_safe(std::uint64_t seq, Staircase changed) const {
  for (;;) {
    const Entry& e = at(seq);
    if (e.prev_motion == 0) return true;
    const std::uint64_t m = e.prev_motion - 1;
    const Entry& before = at(m);
    // One before it that holds its end speed reads only the entry limit; one
    // that brakes across it follows its whole staircase.
    const bool no_lower = changed.entry_mm_s >= e.stairs.entry_mm_s - 1e-9 &&
                          (!before.stairs.through || changed.covers(e.stairs));
    if (no_lower) return true;
    if (m < first_open()) return false;
    PlannedCommand c = before.command;
    c.v_end_mm_s = std::min(before.end_cap_mm_s, changed.entry_mm_s);
    changed = prep::settle(c, m, before.caps(), &changed, cycle_s_);
    seq = m;
  }
}

double LookAheadWindow::cruise(const PlannedCommand& c) const { return std::min(c.v_cmd_mm_s, c.limits.v_max_mm_s); }

// The velocity limit at a transition the blend made tangent: what is left
// of a kink (an arc's end radius rounding) by the planner's corner rule,
// and neither side's cruise velocity exceeded.
// Under a jerk-limited slope with the kink rule's budget (CornerUnit), as
// the transition was planned before its blocks were reshaped (a chord
// smoothed into a span turns its start too: with STEP's budget the kink
// at a sharp vertex after a span was passed at 2.5 mm/s, stepping Z's
// acceleration by 440 mm/s^2 in a cycle: property test, seed 80).
double LookAheadWindow::tangent_cap(const PlannedCommand& from, const PlannedCommand& to, const BlendAxes& ax) const {
  motion::AxisVector t_in{}, t_out{};
  from.segment.tangent_at(from.segment.length(), t_in);
  to.segment.tangent_at(0.0, t_out);
  const bool jerk = jerk_limited(from.limits.slope) || jerk_limited(to.limits.slope);
  const auto& dv = jerk ? ax.jerk_corner_dv_mm_s : ax.corner_dv_mm_s;
  return motion::transition_velocity(t_in, t_out, std::span<const double>(dv.data(), ax.n_axes),
                                     jerk ? 0.0 : from.limits.a_dec_mm_s2 * cycle_s_, cruise(from), cruise(to));
}

// The weightings a fillet between two blocks must hold: the lower
// accelerations and longer ramps of both, the kink budget the higher
// acceleration leaves.
WeightScale LookAheadWindow::both(const WeightScale& a, const WeightScale& b) {
  return {std::min(a.acc_min, b.acc_min), std::max(a.acc_max, b.acc_max), std::max(a.ramp_max, b.ramp_max),
          std::max(a.geom, b.geom)};
}

const BlendAxes& LookAheadWindow::weighted_axes(const WeightScale& w) {
  weighted_ = axes_;
  for (std::size_t j = 0; j < weighted_.n_axes; ++j) {
    motion::AxisDynamics& d = weighted_.feed_dyn[j];
    const double a_along = std::max(d.a_acc_mm_s2, d.a_dec_mm_s2);
    const double less = std::min(w.acc_min, 1.0), ramp = std::max(w.ramp_max, 1.0);
    d.a_acc_mm_s2 *= less;
    d.a_dec_mm_s2 *= less;
    d.tr = {d.tr.acc_up_s * ramp, d.tr.acc_down_s * ramp, d.tr.dec_up_s * ramp, d.tr.dec_down_s * ramp};
    d.tr_geom_s *= std::max(w.geom, 1.0);
    weighted_.a_max_mm_s2[j] *= less;
    if (w.acc_max > 1.0)
      weighted_.corner_dv_mm_s[j] = std::max(weighted_.corner_dv_mm_s[j] - (w.acc_max - 1.0) * a_along * cycle_s_, 0.0);
    // a / tr: the lower acceleration over the longer ramp
    weighted_.jerk_corner_dv_mm_s[j] = std::min(weighted_.corner_dv_mm_s[j], axes_.jerk_corner_dv_mm_s[j] * less / ramp);
  }
  return weighted_;
}

// Roughly what a blend costs against the programmed corner at the feed
// (continuous time, to choose between a fillet and a parabola): its own
// time less the trimmed length's, braking into it and speeding up after it.
double LookAheadWindow::corner_cost(const motion::CornerBlend& cb, const motion::PathLimits& l,
                                    const PlannedCommand& before, const PlannedCommand& after) const {
  const double v = std::min({l.v_max_mm_s, before.v_cmd_mm_s, after.v_cmd_mm_s});
  if (!(v > 0)) return std::numeric_limits<double>::infinity();
  const double v_in = cruise(before), v_out = cruise(after);
  const double trim_in = before.segment.length() - cb.before.length();
  const double trim_out = after.segment.length() - cb.after.length();
  return cb.corner.length() / v - trim_in / v_in - trim_out / v_out + ramps_cost(v, before, after);
}

// What braking from the feed to v_mm_s before a corner and speeding up
// after it cost against passing at the feed (continuous time).
double LookAheadWindow::ramps_cost(double v_mm_s, const PlannedCommand& before, const PlannedCommand& after) const {
  const auto ramp = [v_mm_s](double v_feed, double a) {
    return v_mm_s < v_feed && a > 0 ? (v_feed - v_mm_s) * (v_feed - v_mm_s) / (2 * a * v_feed) : 0.0;
  };
  return ramp(cruise(before), before.limits.a_dec_mm_s2) + ramp(cruise(after), after.limits.a_acc_mm_s2);
}

// The blend of the corner between p and next: the fillet, or (both under
// STEP) the parabola where its corner costs less time (corner_cost), each
// sized for the feed (sized_for_feed). A block is shared between its two
// corners: this one may take p's end up to what p's start left of it, and
// next's start up to half of next, each keeping kKeepCycles of travel.
// `limits`: the chosen blend's path limits.
std::optional<motion::CornerBlend> LookAheadWindow::corner_blend(const Entry& p, const PlannedCommand& next,
                                                                 const BlendDynamics& dyn, motion::PathLimits& limits) const {
  const double feed = std::min(cruise(p.command), cruise(next));
  const double trim_a = p.command.segment.length() - kKeepCycles * cycle_s_ * cruise(p.command);
  const double trim_b = 0.5 * (next.segment.length() - kKeepCycles * cycle_s_ * cruise(next));
  if (!(trim_a > 0 && trim_b > 0)) return std::nullopt;
  const auto bounds = [&](double share) { return motion::BlendBounds{p.command.blend_dev_mm, trim_a, trim_b, share}; };
  // Sized with the fillet's least share for speeding up and braking, run
  // with what its turn at the feed leaves (fillet_limits).
  const motion::AxisVector k_before = motion::end_curvature(p.command.segment, true);
  const motion::AxisVector k_after = motion::end_curvature(next.segment, false);
  const auto fillet_limits_of = [&](const motion::Segment& f, double feed_mm_s) {
    motion::PathLimits l = jerk_fillet_limits(f, dyn, p.command.limits, feed_mm_s);
    if (jerk_limited(l.slope)) l.v_max_mm_s = std::min(l.v_max_mm_s, curvature_step_speed(f, k_before, k_after, dyn, cycle_s_));
    return l;
  };
  auto cb = sized_for_feed([&](double share) { return motion::blend_corner(p.command.segment, next.segment, bounds(share)); },
                           [&](const motion::Segment& f) { return fillet_limits_of(f, 0.0); }, feed, cycle_s_, limits);
  if (cb) limits = fillet_limits_of(cb->corner, feed);
  // STEP only: a parabola's axes change their acceleration at its ends by
  // up to a_max (no jerk limit could hold there).
  if (p.command.limits.slope != SlopeProfile::step || next.limits.slope != SlopeProfile::step) return cb;
  motion::PathLimits l{};
  const auto cb_parabola = sized_for_feed(
      [&](double share) { return motion::blend_corner_parabola(p.command.segment, next.segment, bounds(share)); },
      [&](const motion::Segment& z) { return parabola_limits(z, dyn); }, feed, cycle_s_, l);
  if (!cb_parabola) return cb;
  if (cb && corner_cost(*cb, limits, p.command, next) <= corner_cost(*cb_parabola, l, p.command, next)) return cb;
  limits = l;
  return cb_parabola;
}

// Puts a blend (fillet or parabola) between the open motion `prev` and
// `next` (about to be appended): shortens both, appends the blend as a
// motion of prev's block and makes it the open motion. False (nothing
// changed) where no blend fits or it would not let the path pass faster
// than the sharp corner.
bool LookAheadWindow::blend(std::uint64_t prev, PlannedCommand& next) {
  Entry& p = at(prev);
  if (axes_.n_axes == 0 || !next.head.feed_motion || next.has<kernel::ProgramMap>() || next.trafo.kind != motion::CaxTrafoKind::none ||
      next.feed_link.kind != kernel::FeedLinkKind::none)
    return false;
  const WeightScale w = both(p.command.weights, next.weights);
  const BlendAxes& ax = w.unit() ? axes_ : weighted_axes(w);
  const BlendDynamics dyn{std::span<const motion::AxisDynamics>(ax.feed_dyn.data(), ax.n_axes),
                          std::span<const double>(ax.a_max_mm_s2.data(), ax.n_axes)};
  // Under a jerk-limited slope also a kink that passes at the feed is
  // smoothed: the spans chain across it, a kink ends the chain.
  if (jerk_limited(p.command.limits.slope) && jerk_limited(next.limits.slope) && smooth(prev, next, ax, dyn)) return true;
  // Only a corner that slows the path gets a fillet (a kink that passes at
  // the feed, like the chords of a fine polygon, stays as programmed).
  const double feed = std::min(cruise(p.command), cruise(next));
  if (next.v_entry_max_mm_s >= 0.999 * feed) return false;
  motion::PathLimits blend_limits{};
  const auto cb = corner_blend(p, next, dyn, blend_limits);
  if (!cb) return false;
  const bool parabola = cb->corner.kind() == motion::SegmentKind::parabola;
  PlannedCommand f;
  f.weights = w;
  f.kind = CommandKind::motion;
  f.head.file_id = p.command.head.file_id;
  f.head.line = p.command.head.line;
  f.head.n = p.command.head.n;
  f.head.emit_block_event = false;  // a follow-up of the block before
  f.segment = cb->corner;
  f.limits = blend_limits;
  f.v_cmd_mm_s = std::min(p.command.v_cmd_mm_s, next.v_cmd_mm_s);
  f.css = p.command.css;
  f.head.feed_motion = true;
  f.manual_offset_axes = p.command.manual_offset_axes;
  if (!motion::valid(f.limits) || cruise(f) <= next.v_entry_max_mm_s) return false;
  // Nor where the blend takes longer than the sharp corner (issue 43, D3):
  // a slow fillet under a jerk-limited slope can take longer to run through
  // than braking to the corner's speed and back.
  if (corner_cost(*cb, f.limits, p.command, next) >= ramps_cost(next.v_entry_max_mm_s, p.command, next)) return false;
  // Every piece must take more than a cycle's travel, or the profile would
  // stand still for a cycle at its end (it carries one cycle at most).
  PlannedCommand before = p.command, after = next;
  before.segment = cb->before;
  after.segment = cb->after;
  widen_arc_limits(before.segment, dyn, false, before.limits);
  widen_arc_limits(after.segment, dyn, true, after.limits);
  const double dt2 = 2 * cycle_s_;
  if (cb->corner.length() < dt2 * cruise(f) || cb->before.length() < dt2 * cruise(before) ||
      cb->after.length() < dt2 * cruise(after))
    return false;
  // The profile passes on at exactly its planned end speed (it holds it over
  // its last cycles) once that is above one braking step; below, the step
  // into the hold may jump it and cross one braking step faster, so a slow
  // fillet is entered that much below its limit.
  const double step_mm_s = before.limits.a_dec_mm_s2 * cycle_s_;
  const double fillet_entry = cruise(f) > 2 * step_mm_s ? cruise(f) : cruise(f) - step_mm_s;
  f.v_entry_max_mm_s = std::max(std::min(tangent_cap(before, f, ax), fillet_entry), 0.0);
  after.v_entry_max_mm_s = tangent_cap(f, after, ax);
  if (f.limits.slope == SlopeProfile::step && after.limits.slope == SlopeProfile::step) {
    after.start_a_mm_s2 =
        parabola ? parabola_pass_acceleration(cb->corner, f.limits, cb->after, after.limits, true, dyn, cycle_s_)
                 : pass_acceleration(cb->corner, f.limits, cb->after, after.limits, dyn, cycle_s_);
    after.pass_in_limited = true;
  }
  // Into the fillet: the block before brakes to the fillet's speed in the
  // cycle that crosses into it (not a cycle earlier) with at most what the
  // fillet's first part leaves of a_max. Worth a lower braking over the
  // whole block only down to kIntoFilletShare of its own.
  if (f.limits.slope == SlopeProfile::step && before.limits.slope == SlopeProfile::step) {
    const double a_in =
        parabola ? parabola_pass_acceleration(cb->corner, f.limits, cb->before, before.limits, false, dyn, cycle_s_)
                 : pass_acceleration(cb->corner, f.limits, cb->before, before.limits, dyn, cycle_s_);
    before.into_fillet = a_in >= kIntoFilletShare * before.limits.a_dec_mm_s2;
    if (before.into_fillet) before.limits.a_dec_mm_s2 = std::min(before.limits.a_dec_mm_s2, a_in);
  }
  // The window's promise: a command that has left can still brake in what
  // follows. Shortening prev may lower the velocities before it (the fillet
  // is slower than a stop is far): fine inside the window, where the chain
  // is planned again, but not for a command already released.
  after.v_end_mm_s = 0;
  const Staircase after_stairs = prep::settle(after, tail_ + 1, EndCaps{}, nullptr, cycle_s_);
  f.v_end_mm_s = std::min(after.v_entry_max_mm_s, after_stairs.entry_mm_s);
  const Staircase f_stairs = prep::settle(f, tail_, EndCaps::both(after.v_entry_max_mm_s), &after_stairs, cycle_s_);
  before.v_end_mm_s = std::min(f.v_entry_max_mm_s, f_stairs.entry_mm_s);
  if (!lowering_is_safe(prev, prep::settle(before, prev, EndCaps::both(f.v_entry_max_mm_s), &f_stairs, cycle_s_)))
    return false;

  p.command.segment = cb->before;
  p.command.limits = before.limits;
  p.command.into_fillet = before.into_fillet;
  next.segment = cb->after;
  next.limits = after.limits;
  next.start_a_mm_s2 = after.start_a_mm_s2;
  next.pass_in_limited = after.pass_in_limited;
  next.v_entry_max_mm_s = after.v_entry_max_mm_s;
  f.v_end_mm_s = 0;
  const std::uint64_t seq = tail_++;
  Entry& e = at(seq);
  e.command = f;
  e.prev_motion = prev + 1;
  e.end_cap_mm_s = e.through_cap_mm_s = 0;
  p.end_cap_mm_s = p.through_cap_mm_s = f.v_entry_max_mm_s;
  open_motion_ = seq + 1;
  raise_chain(seq);
  ++stats_.blends;
  stats_.parabolas += parabola ? 1 : 0;
  stats_.shortfall_mm += cb->shortfall_mm;
  stats_.max_deviation_mm = std::max(stats_.max_deviation_mm, cb->deviation_mm);
  return true;
}

bool LookAheadWindow::smooth(std::uint64_t prev, PlannedCommand& next, const BlendAxes& ax, const BlendDynamics& dyn) {
  Entry& p = at(prev);
  const auto sv = motion::smooth_vertex(p.command.segment, next.segment, p.command.blend_dev_mm);
  if (!sv) return false;
  PlannedCommand before = p.command, after = next;
  before.segment = sv->before;
  after.segment = sv->after;
  before.limits = p.chord_limits;
  // A span keeps its chord's limits and adds what its curvature asks, at
  // its programmed feed at most (as a fillet is sized for it: an override
  // above 100 % does not speed it up).
  for (PlannedCommand* c : {&before, &after}) {
    const motion::PathLimits curve =
        motion::path_limits(c->segment, dyn.feed, c->limits.slope, std::min(c->v_cmd_mm_s, c->limits.v_max_mm_s));
    c->limits.v_max_mm_s = std::min(c->limits.v_max_mm_s, curve.v_max_mm_s);
    c->limits.a_acc_mm_s2 = std::min(c->limits.a_acc_mm_s2, curve.a_acc_mm_s2);
    c->limits.a_dec_mm_s2 = std::min(c->limits.a_dec_mm_s2, curve.a_dec_mm_s2);
    if (!motion::valid(c->limits)) return false;
  }
  after.v_entry_max_mm_s = tangent_cap(before, after, ax);
  if (after.v_entry_max_mm_s < next.v_entry_max_mm_s) return false;
  // As blend(): a command that has left must still be able to brake.
  after.v_end_mm_s = 0;
  const Staircase after_stairs = prep::settle(after, tail_, EndCaps{}, nullptr, cycle_s_);
  before.v_end_mm_s = std::min(after.v_entry_max_mm_s, after_stairs.entry_mm_s);
  if (!lowering_is_safe(prev, prep::settle(before, prev, EndCaps::both(after.v_entry_max_mm_s), &after_stairs, cycle_s_)))
    return false;
  p.command.segment = before.segment;
  p.command.limits = before.limits;
  next_chord_limits_ = next.limits;
  next.segment = after.segment;
  next.limits = after.limits;
  next.v_entry_max_mm_s = next.v_entry_through_max_mm_s = after.v_entry_max_mm_s;  // no kink left
  // The span before now ends curving as it goes on: the vertex at its start,
  // capped while it ended straight (clamped), may be passed faster.
  if (p.prev_motion != 0 && p.prev_motion - 1 >= head_) {
    Entry& m = at(p.prev_motion - 1);
    if (m.command.segment.kind() == motion::SegmentKind::cubic && p.command.v_entry_max_mm_s == m.end_cap_mm_s) {
      p.command.v_entry_max_mm_s = p.command.v_entry_through_max_mm_s = tangent_cap(m.command, p.command, ax);
      m.end_cap_mm_s = m.through_cap_mm_s = std::max(m.end_cap_mm_s, p.command.v_entry_max_mm_s);
      raise_chain(prev);
    }
  }
  ++stats_.smoothed;
  stats_.max_deviation_mm = std::max(stats_.max_deviation_mm, sv->deviation_mm);
  return true;
}

// Whether the motion at `seq` chains into the next one at the full speed of
// the slower of the two (its end cap is theirs, no corner below it).
bool LookAheadWindow::passes_at_cruise(std::uint64_t seq) const {
  const Entry& e = at(seq);
  if (!(e.end_cap_mm_s > 0)) return false;
  for (std::uint64_t n = seq + 1; n < tail_; ++n)
    if (at(n).prev_motion == seq + 1)
      return e.end_cap_mm_s >= std::min(cruise(e.command), cruise(at(n).command)) * (1 - 1e-12);
  return false;
}

bool LookAheadWindow::release(kernel::CommandQueue& q, bool flush) {
  const std::size_t keep = flush ? 0 : depth_;
  while (size() > keep) {
    Entry& e = at(head_);
    e.command.passes_at_cruise = passes_at_cruise(head_);
    if (e.stairs.through) {  // the kernel follows the staircase, which must stay as it is
      e.command.brake_beyond_mm = e.stairs.across_mm;
      e.command.limits.a_dec_mm_s2 = e.stairs.a_mm_s2;
      e.command.v_end_mm_s = e.through_cap_mm_s;  // the ceiling: the staircase sets the speed below it
      fixed_end_ = std::max(fixed_end_, e.stairs.reference + 1);
    }
    if (!packer_.pack(e.command, q)) return false;
    ++head_;
  }
  return true;
}

}  // namespace nck::prep
