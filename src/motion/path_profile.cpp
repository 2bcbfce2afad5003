#include "nck/motion/path_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nck::motion {
namespace {

// Remaining distances below this (1 nm) count as arrived: it absorbs the
// rounding of s += v*dt so the profile never needs an extra crawling cycle.
constexpr double kSnapMm = 1e-9;
constexpr double kNoLimit = std::numeric_limits<double>::infinity();
// A segment passed on at v_end holds it over this many cycles' travel.
constexpr double kHoldCycles = 2.0;

bool positive_finite(double x) noexcept { return std::isfinite(x) && x > 0.0; }

}  // namespace

double discrete_brake_velocity(double remaining_mm, double a_mm_s2, double dt_s) noexcept {
  if (!(remaining_mm > 0.0) || !positive_finite(a_mm_s2) || !positive_finite(dt_s)) return 0.0;
  const double q = a_mm_s2 * dt_s * dt_s;  // distance step of the braking staircase
  if (!std::isfinite(remaining_mm)) return std::numeric_limits<double>::max();
  // Braking from v = n*a*dt (then n-1, ..., 1 steps of a*dt) covers q*n(n+1)/2.
  // n = the largest whole staircase that fits; the rest is spread over its n+1 cycles.
  double n = std::floor((std::sqrt(1.0 + 8.0 * remaining_mm / q) - 1.0) / 2.0);
  n = std::max(n, 0.0);
  // The square root may be off by one ulp either way: fix n exactly.
  if (n > 0.0 && q * n * (n + 1.0) / 2.0 > remaining_mm) n -= 1.0;
  if (q * (n + 1.0) * (n + 2.0) / 2.0 <= remaining_mm) n += 1.0;
  return remaining_mm / (dt_s * (n + 1.0)) + a_mm_s2 * dt_s * n / 2.0;
}

double discrete_brake_distance(double v_mm_s, double a_mm_s2, double dt_s) noexcept {
  if (!(v_mm_s > 0.0) || !positive_finite(a_mm_s2) || !positive_finite(dt_s)) return 0.0;
  const double dv = a_mm_s2 * dt_s;
  const double n = std::floor(v_mm_s / dv);
  return dt_s * (n + 1.0) * (v_mm_s - dv * n / 2.0);
}

double pass_brake_distance(double v_end_mm_s, double a_mm_s2, double dt_s, double hold_cycles) noexcept {
  if (!(v_end_mm_s > 0.0)) return 0.0;
  return discrete_brake_distance(v_end_mm_s, a_mm_s2, dt_s) - hold_cycles * v_end_mm_s * dt_s;
}

double pass_brake_distance(double v_end_mm_s, double a_mm_s2, double dt_s) noexcept {
  return pass_brake_distance(v_end_mm_s, a_mm_s2, dt_s, kHoldCycles);
}

double duration_estimate(double length_mm, double v_cmd_mm_s, const PathLimits& limits) noexcept {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!(length_mm > 0.0)) return 0.0;
  if (!std::isfinite(length_mm) || !valid(limits) || !(v_cmd_mm_s > 0.0)) return kInf;
  const double acc = limits.a_acc_mm_s2, dec = limits.a_dec_mm_s2;
  const double v_cruise = std::min(v_cmd_mm_s, limits.v_max_mm_s);
  // Peak of the triangle that just fits: L = v^2/(2 acc) + v^2/(2 dec).
  const double v_tri = std::sqrt(2.0 * length_mm * acc * dec / (acc + dec));
  const double v = std::min(v_cruise, v_tri);
  const double ramp_mm = v * v / (2.0 * acc) + v * v / (2.0 * dec);
  return v / acc + v / dec + std::max(length_mm - ramp_mm, 0.0) / v;
}

void PathProfile::reset() noexcept {
  length_mm_ = 0.0;
  s_mm_ = 0.0;
  v_mm_s_ = 0.0;
  carry_mm_ = 0.0;
  finished_ = true;
  jerk_ = false;
  a_mm_s2_ = carry_s_ = 0.0;
  chain_ = PathChain{};
  emergency_a_mm_s2_ = 0.0;
}

void PathProfile::brake_for_emergency(double a_mm_s2) noexcept {
  if (!positive_finite(a_mm_s2)) return;
  emergency_a_mm_s2_ = a_mm_s2;
  // A jerk-limited plan in force hands over at the speed it has now.
  jerk_ = false;
  a_mm_s2_ = carry_s_ = 0.0;
  beyond_dt_s_ = 0.0;
}

bool PathProfile::start(double length_mm, double v_cmd_mm_s, const PathLimits& limits, double v_end_mm_s,
                        const PathChain& chain) noexcept {
  if (!std::isfinite(v_mm_s_) || v_mm_s_ < 0.0) v_mm_s_ = 0.0;
  const double carry = carry_mm_;
  carry_mm_ = 0.0;
  // Passing in from the segment before: the cycle that crossed over lay on
  // both, so the first step here changes the speed by no more than either
  // allows (a line after a fillet would otherwise add its full acceleration
  // to what is left of the fillet's turn).
  const bool passing = v_mm_s_ > 0.0 && valid(limits_);
  first_acc_mm_s2_ = passing ? limits_.a_acc_mm_s2 : kNoLimit;
  first_dec_mm_s2_ = passing ? limits_.a_dec_mm_s2 : kNoLimit;
  limits_ = limits;
  v_end_mm_s_ = 0.0;
  v_limit_mm_s_ = -1.0;
  override_ignored_ = false;
  into_fillet_ = false;
  through_mm_ = 0.0;
  if (!std::isfinite(length_mm) || length_mm < 0.0) {
    length_mm_ = s_mm_ = 0.0;
    finished_ = true;
    return false;
  }
  length_mm_ = length_mm;
  if (length_mm <= kSnapMm) {  // nothing to move: done at once
    s_mm_ = length_mm;
    finished_ = true;
    return true;
  }
  if (!valid(limits) || !positive_finite(v_cmd_mm_s)) {
    length_mm_ = s_mm_ = 0.0;
    finished_ = true;
    return false;
  }
  v_cmd_mm_s_ = std::min(v_cmd_mm_s, limits.v_max_mm_s);
  beyond_dt_s_ = 0.0;  // recomputed at the first step
  if (positive_finite(v_end_mm_s)) v_end_mm_s_ = std::min(v_end_mm_s, v_cmd_mm_s_);
  finished_ = false;
  jerk_ = jerk_limited(limits.slope) && valid(jerk_limits(limits)) && !emergency();
  // A chain of one segment is the segment itself.
  const bool chain_on = jerk_ && chain.length_mm > length_mm + kSnapMm && valid(jerk_limits(chain.limits));
  chain_ = chain_on ? chain : PathChain{};
  chain_changed_ = false;
  if (jerk_) {
    start_jerk(carry, passing);
    return true;
  }
  a_mm_s2_ = carry_s_ = 0.0;
  s_mm_ = std::min(carry, length_mm);
  return true;
}

void PathProfile::set_end_velocity(double v_end_mm_s) noexcept {
  const double v = positive_finite(v_end_mm_s) ? std::min(v_end_mm_s, v_cmd_mm_s_) : 0.0;
  if (v == 0.0 && chained()) {  // a stop at this segment's end: the chain ends here
    chain_ = PathChain{};
    plan_end_mm_s_ = -1.0;  // plan anew
  }
  if (v == v_end_mm_s_) return;
  v_end_mm_s_ = v;
  beyond_dt_s_ = 0.0;  // the braking curve's end point moves
}

bool PathProfile::stop_fits(double dt_s) const noexcept {
  const double left_mm = remaining();
  if (jerk_) return change_distance(v_mm_s_, a_mm_s2_, 0.0, jerk_limits(limits_)) <= left_mm + kSnapMm;
  return v_mm_s_ <= discrete_brake_velocity(left_mm, limits_.a_dec_mm_s2, dt_s);
}

void PathProfile::limit_first_step(double a_mm_s2) noexcept {
  if (a_mm_s2 >= 0.0) first_acc_mm_s2_ = std::min(first_acc_mm_s2_, a_mm_s2);  // NaN: ignored
}

void PathProfile::pass_into_fillet() noexcept {
  if (jerk_ || into_fillet_) return;
  into_fillet_ = true;
  beyond_dt_s_ = 0.0;  // the braking curve's end point moves a cycle on
}

void PathProfile::brake_through(double beyond_mm) noexcept {
  if (jerk_ || !(beyond_mm > 0.0) || !std::isfinite(beyond_mm)) return;
  through_mm_ = beyond_mm;
  beyond_dt_s_ = 0.0;  // the braking curve's end point moves
}

void PathProfile::pass_first_step(double a_mm_s2) noexcept {
  if (!(a_mm_s2 >= 0.0)) return;  // NaN: ignored
  first_acc_mm_s2_ = first_dec_mm_s2_ = a_mm_s2;
}

void PathProfile::set_velocity_limit(double v_mm_s) noexcept {
  v_limit_mm_s_ = std::isfinite(v_mm_s) && v_mm_s >= 0.0 ? v_mm_s : -1.0;
}

double PathProfile::target_velocity(double override_factor) const noexcept {
  if (override_ignored_) override_factor = 1.0;
  if (!(override_factor > 0.0)) return 0.0;  // also NaN: hold rather than guess
  // The override scales the coupling's limit as it scales F.
  const double v = v_limit_mm_s_ >= 0.0 ? std::min(v_cmd_mm_s_, v_limit_mm_s_) : v_cmd_mm_s_;
  return std::min(v * override_factor, limits_.v_max_mm_s);
}

ProfileSample PathProfile::finish(double v_step_mm_s, double v_prev_mm_s, double dt_s,
                                  double past_end_mm) noexcept {
  s_mm_ = length_mm_;
  finished_ = true;
  const bool flying = v_end_mm_s_ > 0.0;
  v_mm_s_ = flying ? v_step_mm_s : 0.0;
  carry_mm_ = flying ? std::max(past_end_mm, 0.0) : 0.0;
  return ProfileSample{s_mm_, v_step_mm_s, (v_step_mm_s - v_prev_mm_s) / dt_s, true};
}

ProfileSample PathProfile::step(double dt_s, double override_factor) noexcept {
  if (finished_) {
    // Stepping past the end means the path stopped there.
    v_mm_s_ = 0.0;
    carry_mm_ = 0.0;
    a_mm_s2_ = carry_s_ = 0.0;
    return ProfileSample{s_mm_, 0.0, 0.0, true};
  }
  if (jerk_) return step_jerk(dt_s, override_factor);
  if (!positive_finite(dt_s)) return ProfileSample{s_mm_, v_mm_s_, 0.0, false};
  const double v_prev = v_mm_s_;
  const double left_mm = length_mm_ - s_mm_;
  if (left_mm <= kSnapMm) return finish(left_mm / dt_s, v_prev, dt_s, 0.0);

  const double target = target_velocity(override_factor);
  const double a_acc = std::min(limits_.a_acc_mm_s2, first_acc_mm_s2_);
  const double a_dec = std::max(std::min(limits_.a_dec_mm_s2, first_dec_mm_s2_), emergency_a_mm_s2_);
  first_acc_mm_s2_ = first_dec_mm_s2_ = kNoLimit;
  // Passing on at v_end > 0: over the last cycles before the end the
  // profile runs at v_end (pass_brake_distance), so it crosses at exactly
  // that speed.
  const double hold_cycles = into_fillet_ ? 1.0 : kHoldCycles;
  const bool holding = v_end_mm_s_ > 0.0 && left_mm <= hold_cycles * v_end_mm_s_ * dt_s;
  bool braking = false;
  const double goal = holding ? std::min(target, v_end_mm_s_) : target;
  double v = v_prev < goal ? std::min(v_prev + a_acc * dt_s, goal) : std::max(v_prev - a_dec * dt_s, goal);
  // Rounding must not leave a residue like 1e-14 mm/s (a "moving" feedhold).
  if (std::abs(v - goal) <= 1e-12 * std::max(1.0, goal)) v = goal;
  // Braking curve: to standstill at the end, or (passing on) to v_end where
  // the hold begins, which is the curve to standstill at a point beyond it.
  const double a = limits_.a_dec_mm_s2;
  // Far from the end a braking curve is not reached: it lies above
  // sqrt(2 a d) - a dt / 2, so the staircase is skipped there.
  const auto brake_towards = [&](double rest_mm) {
    const double v_safe = v + 1.5 * a * dt_s;
    if (v_safe * v_safe <= 2.0 * a * rest_mm) return;
    const double v_brake = discrete_brake_velocity(rest_mm, a, dt_s);
    braking = braking || v_brake < v;
    v = std::min(v, v_brake);
  };
  if (!holding) {
    if (dt_s != beyond_dt_s_) {  // once per segment and cycle time
      beyond_mm_ = pass_brake_distance(v_end_mm_s_, a, dt_s, hold_cycles);
      beyond_dt_s_ = dt_s;
    }
    brake_towards(left_mm + beyond_mm_);
  }
  // Braking across the end: the staircase of the segments after it as well
  // (v_end is then the ceiling its corner sets).
  const bool through = through_mm_ > 0.0;
  if (through) brake_towards(left_mm + through_mm_);
  v = std::max(v, 0.0);

  // The cycle that passes into the next segment lies on both (a fillet's
  // turn starts or ends in it): it keeps the speed it had. Into a fillet it
  // takes the speed to pass at instead (the fillet's first part turns by at
  // most half its centripetal acceleration in it, and the window gave this
  // segment no acceleration beyond what that leaves of a_max).
  // Braking across the end, it may go on braking in it. Out of a
  // standstill just before the end (a feedhold that stopped there), the step
  // reaches the end and no further: its speed-up is this segment's, which
  // the next one's direction may turn into more than an axis's a_max.
  if (v_end_mm_s_ > 0.0 && v * dt_s >= left_mm - kSnapMm) {
    if (!(v_prev > 0.0)) v = left_mm / dt_s;
    else if (through) v = std::min(v, v_prev);
    else v = into_fillet_ ? std::clamp(std::min(target, v_end_mm_s_), v_prev - a_dec * dt_s, v_prev) : v_prev;
  }
  const double move_mm = v * dt_s;
  if (move_mm >= left_mm - kSnapMm) {
    // Stopping at the end: report the speed that covers exactly what was left.
    const double v_step = v_end_mm_s_ > 0.0 ? v : left_mm / dt_s;
    return finish(v_step, v_prev, dt_s, move_mm - left_mm);
  }
  s_mm_ += move_mm;
  v_mm_s_ = v;
  return ProfileSample{s_mm_, v, (v - v_prev) / dt_s, false, braking};
}

}  // namespace nck::motion
