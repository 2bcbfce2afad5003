// PathProfile under a jerk-limited slope (TRAPEZ, SIN2, HSC): the segment
// follows a JerkPlan, sampled at the cycle times. Replanning starts from
// the exact state (position, velocity, acceleration) at the last sample,
// so the acceleration never jumps; the time a cycle runs past the
// segment's end is carried into the next segment's plan, whose start state
// is the crossing state, so passing at speed is exact too. Under HSC the
// plan reaches over the chain of segments after this one (PathChain): it
// ends at the chain's end, so the acceleration goes on across the
// segments' ends inside it.
#include <algorithm>
#include <cmath>

#include "nck/motion/path_profile.hpp"

namespace nck::motion {
namespace {

constexpr double kSnapMm = 1e-9;  // as in path_profile.cpp
constexpr int kCrossingBisections = 60;
// HSC: a chain that grew is planned in when the plan in force begins to
// brake within this time (before, the longer chain changes nothing yet).
constexpr double kChainReplanAheadS = 0.05;

}  // namespace

void PathProfile::start_jerk(double carry_mm, bool passing) noexcept {
  // The time already run into this segment: the jerk-limited segment before
  // hands it on exactly; after a STEP segment its distance at its speed.
  double carry_s = carry_s_;
  if (!(carry_s > 0.0)) carry_s = carry_mm > 0.0 && v_mm_s_ > 0.0 ? carry_mm / v_mm_s_ : 0.0;
  carry_s_ = 0.0;
  if (!passing) a_mm_s2_ = 0.0;
  s_mm_ = 0.0;
  replan_jerk(target_velocity(last_override_));
  t_s_ = std::max(carry_s, 0.0);
  const Kinematics k = plan_.at(t_s_);
  s_mm_ = std::min(plan_s0_mm_ + k.s_mm, length_mm_);
  if (t_s_ > 0.0) {
    v_mm_s_ = k.v_mm_s;
    a_mm_s2_ = k.a_mm_s2;
  }
}

// A new plan from the state now over what is left of the segment (HSC:
// of the chain).
void PathProfile::replan_jerk(double target_mm_s, bool may_keep) noexcept {
  const bool chain = chained();
  const JerkLimits l = jerk_limits(chain ? chain_.limits : limits_);
  const double length_mm = chain ? chain_.length_mm : length_mm_;
  const double v_end = chain ? std::min(chain_.v_end_mm_s, target_mm_s) : v_end_mm_s_;
  const Kinematics now{0.0, v_mm_s_, a_mm_s2_};
  // A new target late in a ramp that the slope could not take back before
  // the speed passes 0 or the limit (a feedhold released late in its
  // braking, an override lowered late in a speed-up; SIN2 ramps so, since a
  // ramp planned anew starts at jerk 0 where the one under way is at its
  // peak): the plan in force goes on within the limits, and the new target
  // is tried again from the next cycle's state (a plan from here would
  // reverse, overshoot or step the acceleration).
  const double v_max = (chain ? chain_.limits : limits_).v_max_mm_s;
  if (may_keep && ramp_outruns(now, l, v_max)) return;
  // Past the end only with a successor to go on braking in.
  JerkPlan next;
  const BlockPlanKind kind = plan_block(next, now, length_mm - s_mm_, target_mm_s, v_end, l, v_end > 0.0);
  // A new target that a plan from here could only meet past the end (or
  // with ramps shorter than the slope's, "forced"): the plan in force meets
  // the end speed within the limits (a plan that "just fits" cannot always
  // be planned again from its own later states: a new SIN2 ramp starts at
  // jerk 0 where the ramp under way is at its peak), and passing the end
  // faster would break the corner's or the fillet's speed (an acceleration
  // jump at a kink). It stays; the next segment takes the new target (a
  // feedhold brakes on there, an override step rises there).
  plan_target_mm_s_ = target_mm_s;
  if (may_keep && !chain && kind != BlockPlanKind::fits && plan_kind_ != BlockPlanKind::overrun) return;
  plan_ = next;
  plan_kind_ = kind;
  plan_s0_mm_ = s_mm_;
  t_s_ = 0.0;
  plan_end_mm_s_ = v_end_mm_s_;
  chain_changed_ = false;
}

void PathProfile::set_chain(const PathChain& chain) noexcept {
  if (!jerk_ || finished_) return;
  if (!(chain.length_mm > length_mm_ + kSnapMm) || !valid(jerk_limits(chain.limits))) {
    // The chain ends with this segment now: its own end speed is the chain's.
    if (chained()) {
      chain_ = PathChain{};
      plan_end_mm_s_ = -1.0;  // plan anew
    }
    set_end_velocity(chain.v_end_mm_s);
    return;
  }
  if (chain == chain_) return;
  // Shorter, slower at its end or with other limits: plan at once.
  const bool grew = chained() && chain.length_mm >= chain_.length_mm && chain.v_end_mm_s >= chain_.v_end_mm_s;
  chain_ = chain;
  if (grew) chain_changed_ = true;
  else plan_end_mm_s_ = -1.0;
}

ProfileSample PathProfile::step_jerk(double dt_s, double override_factor) noexcept {
  if (!(std::isfinite(dt_s) && dt_s > 0.0)) return ProfileSample{s_mm_, v_mm_s_, 0.0, false};
  last_override_ = override_factor;
  const double target = target_velocity(override_factor);
  const bool chain_due = chain_changed_ && t_s_ + kChainReplanAheadS >= plan_.braking_from_s();
  if (v_end_mm_s_ != plan_end_mm_s_ || chain_due) replan_jerk(target);
  else if (target != plan_target_mm_s_) replan_jerk(target, true);
  const double t1 = t_s_ + dt_s;
  const Kinematics k = plan_.at(t1);
  const double s1 = plan_s0_mm_ + k.s_mm;
  // HSC: inside a chain the plan goes on past this segment's end.
  const bool to_end = plan_kind_ != BlockPlanKind::overrun && !chained();
  if (s1 >= length_mm_ - kSnapMm || (to_end && t1 >= plan_.duration())) {
    if (to_end) return finish_jerk(std::min(plan_.duration(), t1), t1);
    // Overrun: when within the cycle the path crossed the end.
    double lo = t_s_, hi = t1;
    for (int i = 0; i < kCrossingBisections; ++i) {
      const double mid = (lo + hi) / 2.0;
      (plan_s0_mm_ + plan_.at(mid).s_mm < length_mm_ ? lo : hi) = mid;
    }
    return finish_jerk(hi, t1);
  }
  const bool braking = k.a_mm_s2 < 0.0 && t1 >= plan_.braking_from_s();
  t_s_ = t1;
  s_mm_ = s1;
  v_mm_s_ = k.v_mm_s;
  a_mm_s2_ = k.a_mm_s2;
  return ProfileSample{s_mm_, v_mm_s_, a_mm_s2_, false, braking};
}

// The segment ends at plan time t_end_s within the cycle that ends at t1_s.
ProfileSample PathProfile::finish_jerk(double t_end_s, double t1_s) noexcept {
  const Kinematics k = plan_.at(t_end_s);
  s_mm_ = length_mm_;
  finished_ = true;
  const bool flying = (v_end_mm_s_ > 0.0 || chained()) && k.v_mm_s > 0.0;
  v_mm_s_ = flying ? k.v_mm_s : 0.0;
  a_mm_s2_ = flying ? k.a_mm_s2 : 0.0;
  carry_s_ = flying ? std::max(t1_s - t_end_s, 0.0) : 0.0;
  carry_mm_ = carry_s_ * v_mm_s_;  // for a STEP segment after it
  return ProfileSample{s_mm_, k.v_mm_s, k.a_mm_s2, true, false};
}

}  // namespace nck::motion
