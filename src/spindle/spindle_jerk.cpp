// The jerk-limited ramps of the spindle interpolator (getriebe[i].slope_type,
// P-AXIS-00270: 1 TRAPEZ, 2 SIN2). The speed changes and the exact stops
// of M19, homing and the gear-change approach follow motion::JerkPlan, the
// closed-form profile the path uses, with a_beschl / a_brems (G130 and the
// caps applied as for STEP) and the four feed ramp times. The plan is
// sampled at the cycle times; a changed goal or limit (S, override,
// feedhold, tool) replans from the exact state at the last sample, so the
// acceleration never jumps.
#include <algorithm>
#include <cmath>

#include "nck/spindle/spindle_axis.hpp"

namespace nck::spindle {
namespace {
int sign_of(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
}  // namespace

motion::JerkLimits SpindleAxis::jerk_limits() const noexcept {
  const GearConfig& g = gear();
  const motion::RampTimes& tr = g.ramp_times;
  return motion::JerkLimits{accel_limit(g.accel_deg_s2), accel_limit(g.decel_deg_s2), tr.acc_up_s, tr.acc_down_s,
                            tr.dec_up_s, tr.dec_down_s, g.slope == SlopeProfile::sin2};
}

double SpindleAxis::jerk_stop_distance_deg(double speed_deg_s, int dir) const noexcept {
  return motion::change_distance(speed_deg_s, dir * jerk_.a_deg_s2, 0.0, jerk_limits());
}

// True while the plan in force takes its acceleration back to 0 and
// `goal_deg_s` (signed) lies behind the speed that ramp ends at: a new
// plan then waits for the ramp's end (at most a ramp time). A SIN2 ramp
// restarted halfway gains more speed than the rest of the one it replaces
// and would carry the speed past that end, above vb_max or onto the
// target; a TRAPEZ plan would only repeat the rest.
bool SpindleAxis::jerk_plan_settling(double goal_deg_s) const noexcept {
  if (jerk_.kind == JerkRamp::Kind::none) return false;
  const motion::JerkPlan& p = jerk_.plan;
  for (std::size_t i = 0; i < p.phases(); ++i) {
    if (jerk_.t_s < p.phase_start_s(i) || jerk_.t_s >= p.phase_start_s(i + 1)) continue;
    const motion::JerkPhase& ph = p.phase(i);
    if (ph.a1_mm_s2 != 0 || ph.a0_mm_s2 == 0) return false;
    const double goal = jerk_.dir * goal_deg_s, v_end = p.phase_start_state(i + 1).v_mm_s;
    return ph.a0_mm_s2 > 0 ? goal < v_end : goal > v_end;
  }
  return false;
}

void SpindleAxis::jerk_ramp_to(double target, double dt) noexcept {
  jerk_.used = true;
  const double v = set_.vel_deg_s, a = jerk_.a_deg_s2;
  // Reversing goes through standstill: to 0 first, then the other way.
  const int moving = sign_of(v) != 0 ? sign_of(v) : sign_of(a);
  const double goal = (moving != 0 && sign_of(target) == -moving) ? 0.0 : target;
  if (goal == v && a == 0) {  // at speed or at rest: nothing to plan
    jerk_.kind = JerkRamp::Kind::none;
    if (v != 0) advance(v * dt);
    return;
  }
  const int dir = moving != 0 ? moving : sign_of(goal);
  const double goal_mag = dir * goal;
  const motion::JerkLimits lim = jerk_limits();
  const bool same = jerk_.kind == JerkRamp::Kind::speed && jerk_.dir == dir && jerk_.goal_deg_s == goal_mag &&
                    jerk_.limits == lim;
  if (!same && !jerk_plan_settling(goal)) {
    jerk_.plan.reset(motion::Kinematics{0.0, dir * v, dir * a}, lim.sin2);
    jerk_.plan.append_change(goal_mag, lim);
    jerk_.kind = JerkRamp::Kind::speed;
    jerk_.dir = dir;
    jerk_.goal_deg_s = goal_mag;
    jerk_.limits = lim;
    jerk_.t_s = jerk_.s_deg = 0;
  }
  follow_jerk_plan(dt, jerk_.dir * jerk_.goal_deg_s);  // a waiting goal comes next cycle
}

// One cycle further on the plan. At its end the set speed is `end_deg_s`
// exactly (the plan's sums may differ in the last bits) and the
// acceleration 0.
void SpindleAxis::follow_jerk_plan(double dt, double end_deg_s) noexcept {
  jerk_.t_s += dt;
  const motion::Kinematics k = jerk_.plan.at(jerk_.t_s);
  const double ds = k.s_mm - jerk_.s_deg;
  jerk_.s_deg = k.s_mm;
  if (jerk_.t_s >= jerk_.plan.duration()) {
    set_.vel_deg_s = end_deg_s;
    jerk_.a_deg_s2 = 0;
    jerk_.kind = JerkRamp::Kind::none;
  } else {
    set_.vel_deg_s = jerk_.dir * k.v_mm_s;
    jerk_.a_deg_s2 = jerk_.dir * k.a_mm_s2;
  }
  advance(jerk_.dir * ds);
}

// Before a positioning is planned: a speed ramp that is taking its
// acceleration back to 0 runs to its end first (at most a ramp time), for
// the reason jerk_plan_settling gives. True while it does.
bool SpindleAxis::jerk_finish_speed_ramp(double dt) noexcept {
  if (jerk_.kind != JerkRamp::Kind::speed || !jerk_plan_settling(0.0)) return false;
  jerk_.used = true;
  follow_jerk_plan(dt, jerk_.dir * jerk_.goal_deg_s);
  return true;
}

// Plans the stop on the target from the state reached. A replan (the
// override or feedhold changed the speed) that could only stop in time
// with shortened ramps keeps the plan in force instead, which stops there
// within the jerk: a SIN2 ramp restarted halfway needs a little more
// distance than the rest of the one it replaces, and a tight stop is
// braking already.
void SpindleAxis::plan_positioning_ramp(double remaining_deg, double v_cap_deg_s,
                                        const motion::JerkLimits& lim) noexcept {
  const double u = std::max(0.0, pos_.dir * set_.vel_deg_s);
  const motion::Kinematics start{0.0, u, pos_.dir * jerk_.a_deg_s2};
  const bool replan = jerk_.kind == JerkRamp::Kind::positioning;
  motion::JerkPlan plan;
  if (motion::plan_block(plan, start, remaining_deg, v_cap_deg_s, 0.0, lim, false) !=
          motion::BlockPlanKind::forced ||
      !replan) {
    jerk_.plan = plan;
    jerk_.length_deg = remaining_deg;
    jerk_.t_s = jerk_.s_deg = 0;
  }
  jerk_.kind = JerkRamp::Kind::positioning;
  jerk_.dir = pos_.dir;
  jerk_.goal_deg_s = v_cap_deg_s;
  jerk_.limits = lim;
}

// The exact stop on the target: plan_block over the distance to go, up to
// the positioning speed and down to 0 at the target with acceleration 0
// (plan_positioning added turns where the stop needs them, so the plan
// fits). The last sample lands on the target.
void SpindleAxis::jerk_step_positioning(double dt) noexcept {
  jerk_.used = true;
  const double remaining = pos_.remaining_deg;
  if (remaining <= 0) {
    set_.vel_deg_s = 0;
    jerk_.a_deg_s2 = 0;
    jerk_.kind = JerkRamp::Kind::none;
    pos_.done = true;
    return;
  }
  const double v_cap = positioning_speed_deg_s();
  const motion::JerkLimits lim = jerk_limits();
  if ((jerk_.kind != JerkRamp::Kind::positioning || jerk_.goal_deg_s != v_cap || !(jerk_.limits == lim)) &&
      !jerk_plan_settling(pos_.dir * v_cap))
    plan_positioning_ramp(remaining, v_cap, lim);
  jerk_.t_s += dt;
  const motion::Kinematics k = jerk_.plan.at(jerk_.t_s);
  if (jerk_.t_s >= jerk_.plan.duration() || k.s_mm >= jerk_.length_deg) {
    advance(pos_.dir * remaining);  // onto the target, never beyond
    pos_.remaining_deg = 0;
    set_.vel_deg_s = 0;
    jerk_.a_deg_s2 = 0;
    jerk_.kind = JerkRamp::Kind::none;
    return;
  }
  // The plan's last bits may round a hair below 0 at the end: never backwards.
  advance(pos_.dir * std::max(0.0, k.s_mm - jerk_.s_deg));
  jerk_.s_deg = std::max(jerk_.s_deg, k.s_mm);
  set_.vel_deg_s = pos_.dir * std::max(0.0, k.v_mm_s);
  jerk_.a_deg_s2 = pos_.dir * k.a_mm_s2;
  pos_.remaining_deg = jerk_.length_deg - jerk_.s_deg;
}

}  // namespace nck::spindle
