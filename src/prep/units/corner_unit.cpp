// What the look-ahead needs of each motion block (docs/decisions.md,
// "Continuous path and corner blending"): whether it must end at standstill,
// and how fast the path may pass into it from the motion planned before it.
#include <algorithm>
#include <cmath>
#include <limits>

#include "nck/motion/junction.hpp"
#include "nck/prep/units/corner_unit.hpp"

namespace nck::prep {

namespace {

// A kink under a jerk-limited slope (TF5200 P-AXIS-00013 a_trans_weight):
// its velocity step, taken within one cycle, is an acceleration for that
// cycle of at most a * weight; the default weight (0) is cycle time / ramp
// time, so that the acceleration's step stays within the jerk a / tr (the
// smallest of the axis's: the smaller a over the longest ramp time, as HSC
// uses in every phase).
double jerk_limited_kink_dv(const motion::AxisDynamics& d, double weight, double dt_s) {
  if (weight > 0) return std::max(d.a_acc_mm_s2, d.a_dec_mm_s2) * weight * dt_s;
  const motion::RampTimes& t = d.tr;
  const double tr_s = std::max({t.acc_up_s, t.acc_down_s, t.dec_up_s, t.dec_down_s});
  return std::min(d.a_acc_mm_s2, d.a_dec_mm_s2) / tr_s * dt_s * dt_s;
}

// A kink passed at speed under STEP turns the axes within the cycle that
// crosses it and the one after: the crossing cycle keeps its speed
// (PathProfile::step) and the cycle before holds it, so no along-path
// acceleration shares those two cycles but the first step after the kink,
// which the next motion limits to what the turn leaves
// (kink_pass_acceleration). The turn may so take this share of a_max even
// where the feed accelerations equal a_max (issue 43, D2: every kink was a
// stop there); the rest stays for that first step.
constexpr double kKinkShare = 0.5;

}  // namespace

// setup: each axis's velocity budget for a kink. Along the path an axis
// accelerates with up to max(a_acc, a_dec) of the block's mode; a kink in a
// cycle that may also do so (braking across it) adds only what is left of
// a_max; passing at speed it may take kKinkShare of a_max; under a
// jerk-limited slope no more than its jerk allows.
CornerUnit::KinkBudgets CornerUnit::kink_budgets(const AxisTable& axes, const AxisDynamicsArray& dyn, double dt_s) {
  KinkBudgets dv;
  for (std::size_t j = 0; j < axes.count(); ++j) {
    const double a_max = axes.accel_cap_mm_s2(j);
    dv.step_mm_s[j] = std::max(a_max - std::max(dyn[j].a_acc_mm_s2, dyn[j].a_dec_mm_s2), 0.0) * dt_s;
    dv.passing_mm_s[j] = std::max(dv.step_mm_s[j], kKinkShare * a_max * dt_s);
    dv.jerk_limited_mm_s[j] = std::min(dv.step_mm_s[j], jerk_limited_kink_dv(dyn[j], axes.trans_weight(j), dt_s));
  }
  return dv;
}

// The first step after passing from t_in into t_out at up to v: the largest
// acceleration along t_out at which no axis's turn (at most v |t_out - t_in|
// in that step) and the step together exceed its a_max.
double CornerUnit::kink_pass_acceleration(const motion::AxisVector& t_in, const motion::AxisVector& t_out,
                                          double v_mm_s, const PlanContext& ctx, double dt_s) {
  double a = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < ctx.n_axes; ++j) {
    if (std::fabs(t_out[j]) < 1e-12) continue;
    const double turn_mm_s2 = v_mm_s * std::fabs(t_out[j] - t_in[j]) / dt_s;
    a = std::min(a, (ctx.axes.accel_cap_mm_s2(j) - turn_mm_s2) / std::fabs(t_out[j]));
  }
  return std::max(a, 0.0);
}

CornerUnit::CornerUnit(const AxisTable& axes, std::uint32_t cycle_time_us) {
  cycle_s_ = cycle_time_us * 1e-6;
  feed_ = kink_budgets(axes, axes.dynamics(false), cycle_s_);
  rapid_ = kink_budgets(axes, axes.dynamics(true), cycle_s_);
}

void CornerUnit::set_feed_dynamics(const AxisTable& axes, const AxisDynamicsArray& feed) {
  feed_ = kink_budgets(axes, feed, cycle_s_);
}

BlendAxes CornerUnit::blend_axes(const AxisTable& axes) const {
  BlendAxes a;
  a.n_axes = axes.count();
  a.feed_dyn = axes.feed();
  a.corner_dv_mm_s = feed_.step_mm_s;
  a.jerk_corner_dv_mm_s = feed_.jerk_limited_mm_s;
  for (std::size_t j = 0; j < a.n_axes; ++j) a.a_max_mm_s2[j] = axes.accel_cap_mm_s2(j);
  return a;
}

namespace {
// A program map (rotation, mirroring, scaling) applied to a direction.
motion::AxisVector mapped_direction(const PlannedCommand& c, const motion::AxisVector& t, std::size_t n_axes) {
  const auto* map = c.find<kernel::ProgramMap>();
  if (!map) return t;
  motion::AxisVector mapped{}, origin{}, zero{};
  map->map.apply(t, mapped, n_axes);
  map->map.apply(zero, origin, n_axes);
  for (std::size_t j = 0; j < n_axes; ++j) mapped[j] -= origin[j];
  return mapped;
}
}  // namespace

// The unit direction of c's path at its start or end, in machine axes.
motion::AxisVector CornerUnit::machine_tangent(const PlannedCommand& c, bool at_end, std::size_t n_axes) const {
  motion::AxisVector t{};
  c.segment.tangent_at(at_end ? c.segment.length() : 0.0, t);
  return mapped_direction(c, t, n_axes);
}

// The curvature vector of c's path at its start or end, in machine axes.
motion::AxisVector CornerUnit::machine_curvature(const PlannedCommand& c, bool at_end, std::size_t n_axes) const {
  return mapped_direction(c, motion::end_curvature(c.segment, at_end), n_axes);
}

// Coming from an exact stop, the last step into it (at most a_dec * dt
// along the previous path) and c's first step (a * dt along c) fall into
// consecutive cycles: the largest a <= a_acc at which every axis changes its
// velocity by at most a_max * dt between them (a reversal, a sharp turn
// start gently instead of standing still a cycle). Unknown previous
// motion: 0, one cycle at standstill.
double CornerUnit::start_acceleration(const PlannedCommand& c, const PlanContext& ctx) const {
  if (!last_.valid) return 0.0;
  const motion::AxisVector t = machine_tangent(c, false, ctx.n_axes);
  double a = c.limits.a_acc_mm_s2;
  for (std::size_t j = 0; j < ctx.n_axes; ++j) {
    if (std::fabs(t[j]) < 1e-12) continue;
    // |p - a t_j| <= a_max with p the last step's share: a <= (a_max + p sgn t_j) / |t_j|
    const double p = last_.a_dec_mm_s2 * last_.tangent[j];
    a = std::min(a, (ctx.axes.accel_cap_mm_s2(j) + (t[j] > 0 ? p : -p)) / std::fabs(t[j]));
  }
  return std::max(a, 0.0);
}

// Exact stop at c's end: G60 in the block, G360 in force, or a G0 block
// with exact_stop_after_g00 (P-CHAN-00235). The entry limit: the corner
// from the previous motion, and neither block's feed exceeded — a lower F
// is reached before its block starts, a higher one is taken up after the
// transition (the ISG rule).
void CornerUnit::note_transition(const nc::Block& b, PlannedCommand& c, bool rapid, const PlanContext& ctx) {
  const config::ChannelConfig& channel = ctx.channel;
  c.exact_stop = b.g_nonmodal.has(nc::GCode::g60) || b.modal.exact_stop ||
                 (rapid && channel.exact_stop_after_g00);
  // G61 (this block) or G261 (modal): the look-ahead window may blend the
  // corner at this feed motion's end (docs/decisions.md, "Continuous path and
  // corner blending").
  const bool blend = b.g_nonmodal.has(nc::GCode::g61) || b.modal.contour;
  c.blend_dev_mm = blend && !rapid && !c.exact_stop && !c.has<kernel::ProgramMap>() ? b.modal.contour_dev_mm : 0;
  // Under #FACE/#CYL the segment is Cartesian and the machine axes follow
  // the transformation: its corners are not looked ahead yet. A spindle
  // coupling (G95, G33, G63, G331/G332) sets the path speed each cycle from
  // the spindle: such blocks start and end at standstill, except G33 blocks
  // of a thread chain (P-CHAN-00837), which pass on to the next G33 block.
  const bool thread_chain =
      channel.thread_chain && c.trafo.kind == motion::CaxTrafoKind::none && c.feed_link.kind == kernel::FeedLinkKind::thread;
  if (!thread_chain && (c.trafo.kind != motion::CaxTrafoKind::none || c.feed_link.kind != kernel::FeedLinkKind::none)) {
    c.exact_stop = true;
    last_.valid = false;
    return;
  }
  // A chain joins only G33 blocks: the first one starts on the start angle
  // from standstill, the block after the last one from standstill too.
  if (last_.valid && last_.thread != thread_chain) last_.valid = false;
  c.feed_link.chained = thread_chain && last_.valid;
  const KinkBudgets& budgets = rapid ? rapid_ : feed_;
  const bool jerk = jerk_limited(b.modal.slope);
  const auto& dv = jerk ? budgets.jerk_limited_mm_s : budgets.passing_mm_s;
  const auto& through_dv = jerk ? budgets.jerk_limited_mm_s : budgets.step_mm_s;
  const double cruise_mm_s = std::min(c.v_cmd_mm_s, c.limits.v_max_mm_s);
  c.start_a_mm_s2 = start_acceleration(c, ctx);
  if (last_.valid) pass_kink(c, dv, through_dv, cruise_mm_s, jerk, ctx);
  // STEP brakes in whole steps of a_dec * dt and may cross the transition
  // one step faster than planned; a jerk-limited slope ends its braking with
  // the deceleration ramped down to 0, at the planned speed.
  const double braking_step_mm_s = jerk ? 0.0 : c.limits.a_dec_mm_s2 * cycle_s_;
  last_ = {true,
           machine_tangent(c, true, ctx.n_axes),
           jerk ? machine_curvature(c, true, ctx.n_axes) : motion::AxisVector{},
           dv,
           through_dv,
           cruise_mm_s,
           c.limits.a_dec_mm_s2,
           braking_step_mm_s,
           thread_chain};
}

// The entry limits of c from the last motion: passing at speed and braking
// across (each with the smaller budget of both motions); passing at a speed
// whose turn leaves less than c's accelerations, c's first step is limited.
void CornerUnit::pass_kink(PlannedCommand& c, const Budget& dv, const Budget& through_dv, double cruise_mm_s,
                           bool jerk, const PlanContext& ctx) {
  const motion::AxisVector t_out = machine_tangent(c, false, ctx.n_axes);
  // Under a jerk-limited slope a change of curvature steps the axes'
  // acceleration as a kink does (TF5200 P-AXIS-00154 at its 100 %): a
  // tangent arc into a line at speed stepped an axis's acceleration by
  // v^2/r in a cycle.
  const motion::AxisVector k_out = jerk ? machine_curvature(c, false, ctx.n_axes) : motion::AxisVector{};
  const auto entry = [&](const Budget& mine, const Budget& last) {
    Budget budget{};
    for (std::size_t j = 0; j < ctx.n_axes; ++j) budget[j] = std::min(mine[j], last[j]);
    const std::span<const double> dv(budget.data(), ctx.n_axes);
    const double v = motion::transition_velocity(last_.tangent, t_out, dv, last_.braking_step_mm_s, last_.cruise_mm_s,
                                                 cruise_mm_s);
    if (!jerk) return v;
    return std::min(v, motion::curvature_step_velocity(last_.tangent, last_.curvature, t_out, k_out, dv, cycle_s_));
  };
  c.v_entry_max_mm_s = entry(dv, last_.corner_dv);
  c.v_entry_through_max_mm_s = entry(through_dv, last_.through_dv);
  if (jerk || !(c.v_entry_max_mm_s > 0)) return;
  // The path may cross one braking step faster than planned.
  const double v = c.v_entry_max_mm_s + last_.braking_step_mm_s;
  const double a = kink_pass_acceleration(last_.tangent, t_out, v, ctx, cycle_s_);
  if (a >= std::max(c.limits.a_acc_mm_s2, c.limits.a_dec_mm_s2)) return;
  c.start_a_mm_s2 = std::min(c.start_a_mm_s2, a);
  c.pass_in_limited = true;
}

}  // namespace nck::prep
