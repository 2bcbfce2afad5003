#include "nck/motion/jerk_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace nck::motion {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;
// Velocity differences below this count as none (rounding of the sums).
constexpr double kTinyVel = 1e-12;
// Bisections: enough halvings to reach the last bits of a double.
constexpr int kBisections = 64;

bool positive_finite(double x) noexcept { return std::isfinite(x) && x > 0.0; }

// Shape of a ramp at u in [0, 1]: g (acceleration share), its first and
// second integrals G1, G2 (velocity and distance terms).
struct Shape {
  double g, g1, g2;
};

Shape shape(double u, bool sin2) noexcept {
  if (!sin2) return {u, u * u / 2.0, u * u * u / 6.0};
  const double c = std::cos(kPi * u);
  return {(1.0 - c) / 2.0, u / 2.0 - std::sin(kPi * u) / (2.0 * kPi), u * u / 4.0 - (1.0 - c) / (2.0 * kPi * kPi)};
}

Kinematics advance(const Kinematics& k, const JerkPhase& p, double tau, bool sin2) noexcept {
  const double da = p.a1_mm_s2 - p.a0_mm_s2;
  Kinematics out;
  if (da == 0.0 || !(p.t_s > 0.0)) {
    out.a_mm_s2 = p.a0_mm_s2;
    out.v_mm_s = k.v_mm_s + p.a0_mm_s2 * tau;
    out.s_mm = k.s_mm + k.v_mm_s * tau + p.a0_mm_s2 * tau * tau / 2.0;
    return out;
  }
  const double T = p.t_s, u = std::clamp(tau / T, 0.0, 1.0);
  const Shape sh = shape(u, sin2);
  out.a_mm_s2 = p.a0_mm_s2 + da * sh.g;
  out.v_mm_s = k.v_mm_s + p.a0_mm_s2 * tau + da * T * sh.g1;
  out.s_mm = k.s_mm + k.v_mm_s * tau + p.a0_mm_s2 * tau * tau / 2.0 + da * T * T * sh.g2;
  return out;
}

// Accelerations and jerks of one direction of change.
struct Side {
  double a;       // the acceleration limit (magnitude)
  double j_in;    // jerk while the magnitude grows
  double j_out;   // jerk while it shrinks
};

double jerk(double a, double tr_s) noexcept { return tr_s > 0.0 ? a / tr_s : kInf; }

Side up_side(const JerkLimits& l) noexcept {
  return {l.a_acc_mm_s2, jerk(l.a_acc_mm_s2, l.tr_acc_up_s), jerk(l.a_acc_mm_s2, l.tr_acc_down_s)};
}
Side down_side(const JerkLimits& l) noexcept {
  return {l.a_dec_mm_s2, jerk(l.a_dec_mm_s2, l.tr_dec_up_s), jerk(l.a_dec_mm_s2, l.tr_dec_down_s)};
}

// Time to ramp an acceleration magnitude by da at jerk j (0 for a step).
double ramp_time(double da, double j) noexcept { return std::isfinite(j) ? std::abs(da) / j : 0.0; }

}  // namespace

bool valid(const JerkLimits& l) noexcept {
  auto ramp_ok = [](double t) { return std::isfinite(t) && t >= 0.0; };
  return positive_finite(l.a_acc_mm_s2) && positive_finite(l.a_dec_mm_s2) && ramp_ok(l.tr_acc_up_s) &&
         ramp_ok(l.tr_acc_down_s) && ramp_ok(l.tr_dec_up_s) && ramp_ok(l.tr_dec_down_s);
}

void JerkPlan::reset(const Kinematics& start, bool sin2) noexcept {
  n_ = 0;
  sin2_ = sin2;
  ends_[0] = start;
  t_[0] = 0.0;
}

void JerkPlan::push(double t_s, double a0, double a1) noexcept {
  if (!(t_s > 0.0) || n_ >= kMaxPhases) return;
  ph_[n_] = JerkPhase{t_s, a0, a1};
  ends_[n_ + 1] = std::isfinite(t_s) ? advance(ends_[n_], ph_[n_], t_s, sin2_) : ends_[n_];
  t_[n_ + 1] = t_[n_] + t_s;
  ++n_;
}

void JerkPlan::append_cruise(double t_s) noexcept {
  const double a = ends_[n_].a_mm_s2;
  push(t_s, a, a);
}

void JerkPlan::append_change(double v1, const JerkLimits& l) noexcept {
  Kinematics k = ends_[n_];
  const Side up = up_side(l), down = down_side(l);
  // An acceleration in the wrong direction (or one that would carry the
  // velocity past v1 even if taken back at once) goes back to 0 first.
  if (k.a_mm_s2 > 0.0) {
    const double v_nat = k.v_mm_s + k.a_mm_s2 * k.a_mm_s2 / (2.0 * up.j_out);
    if (v1 < v_nat - kTinyVel) {
      push(ramp_time(k.a_mm_s2, up.j_out), k.a_mm_s2, 0.0);
      k = ends_[n_];
    }
  } else if (k.a_mm_s2 < 0.0) {
    const double v_nat = k.v_mm_s - k.a_mm_s2 * k.a_mm_s2 / (2.0 * down.j_out);
    if (v1 > v_nat + kTinyVel) {
      // Taking the braking back at the ramp time would run below 0: take it
      // back faster, so that the path comes to rest instead of reversing.
      const bool reverses = v_nat < 0.0 && v1 <= k.v_mm_s;
      const double t = reverses ? 2.0 * std::max(k.v_mm_s - std::max(v1, 0.0), 0.0) / -k.a_mm_s2
                                : ramp_time(k.a_mm_s2, down.j_out);
      push(t, k.a_mm_s2, 0.0);
      if (reverses) return;
      k = ends_[n_];
    }
  }
  const double dv_signed = v1 - k.v_mm_s;
  if (std::abs(dv_signed) <= kTinyVel && k.a_mm_s2 == 0.0) return;
  const bool rising = k.a_mm_s2 != 0.0 ? k.a_mm_s2 > 0.0 : dv_signed > 0.0;
  const Side sd = rising ? up : down;
  const double sign = rising ? 1.0 : -1.0;
  const double m = std::abs(k.a_mm_s2);
  const double a_lim = std::max(sd.a, m);  // limits lowered under a running ramp: no step
  const double k_in = std::isfinite(sd.j_in) ? 1.0 / (2.0 * sd.j_in) : 0.0;
  const double k_out = std::isfinite(sd.j_out) ? 1.0 / (2.0 * sd.j_out) : 0.0;
  const double dv = std::max(std::abs(dv_signed), m * m * k_out);
  const double dv_full = (a_lim * a_lim - m * m) * k_in + a_lim * a_lim * k_out;
  double a_peak = a_lim, t_hold = 0.0;
  if (dv >= dv_full) {
    t_hold = (dv - dv_full) / a_lim;
  } else {
    a_peak = std::sqrt((dv + m * m * k_in) / (k_in + k_out));
    a_peak = std::clamp(a_peak, m, a_lim);
  }
  push(ramp_time(a_peak - m, sd.j_in), sign * m, sign * a_peak);
  push(t_hold, sign * a_peak, sign * a_peak);
  push(ramp_time(a_peak, sd.j_out), sign * a_peak, 0.0);
  // Steps (ramp time 0) put the acceleration back to 0 without a phase.
  ends_[n_].a_mm_s2 = 0.0;
}

Kinematics JerkPlan::at(double t) const noexcept {
  if (!(t > 0.0)) return ends_[0];
  // Phases are few (<= 12): a linear search is as fast as a binary one.
  std::size_t i = 0;
  while (i < n_ && t >= t_[i + 1]) ++i;
  if (i == n_) {
    Kinematics k = ends_[n_];
    k.s_mm += k.v_mm_s * (t - t_[n_]);
    k.a_mm_s2 = 0.0;
    return k;
  }
  return advance(ends_[i], ph_[i], t - t_[i], sin2_);
}

double JerkPlan::braking_from_s() const noexcept {
  std::size_t i = n_;
  while (i > 0 && ph_[i - 1].a0_mm_s2 <= 0.0 && ph_[i - 1].a1_mm_s2 <= 0.0 &&
         (ph_[i - 1].a0_mm_s2 < 0.0 || ph_[i - 1].a1_mm_s2 < 0.0))
    --i;
  return t_[i];
}

bool ramp_outruns(const Kinematics& k, const JerkLimits& l, double v_max_mm_s) noexcept {
  const double a = k.a_mm_s2;
  if (a < 0.0) return k.v_mm_s - a * a / (2.0 * down_side(l).j_out) < 0.0;
  return a > 0.0 && k.v_mm_s + a * a / (2.0 * up_side(l).j_out) > v_max_mm_s;
}

double change_distance(double v0, double a0, double v1, const JerkLimits& l) noexcept {
  JerkPlan p;
  p.reset(Kinematics{0.0, v0, a0}, l.sin2);
  p.append_change(v1, l);
  return p.end_state().s_mm;
}

namespace {

// Distance of up/down to v_peak and then down to min(v_peak, v_end).
double peak_distance(const Kinematics& k, double v_peak, double v_end, const JerkLimits& l) noexcept {
  JerkPlan p;
  p.reset(Kinematics{0.0, k.v_mm_s, k.a_mm_s2}, l.sin2);
  p.append_change(v_peak, l);
  p.append_change(std::min(v_peak, v_end), l);
  return p.end_state().s_mm;
}

void build(JerkPlan& plan, const Kinematics& start, double v_peak, double v_end, double length_mm,
           const JerkLimits& l) noexcept {
  plan.reset(start, l.sin2);
  plan.append_change(v_peak, l);
  const double before = plan.end_state().s_mm - start.s_mm;
  const double after = peak_distance(Kinematics{0.0, v_peak, 0.0}, v_peak, v_end, l);
  const double cruise_mm = length_mm - before - after;
  if (v_peak > 0.0 && cruise_mm > 0.0) plan.append_cruise(cruise_mm / v_peak);
  else if (v_peak <= 0.0) plan.append_cruise(kInf);  // held (feedhold, a coupling at rest)
  plan.append_change(std::min(v_peak, v_end), l);
}

JerkLimits with_ramps_scaled(JerkLimits l, double f) noexcept {
  l.tr_acc_up_s *= f;
  l.tr_acc_down_s *= f;
  l.tr_dec_up_s *= f;
  l.tr_dec_down_s *= f;
  return l;
}

}  // namespace

BlockPlanKind plan_block(JerkPlan& plan, const Kinematics& start, double length_mm, double v_target,
                         double v_end, const JerkLimits& l, bool allow_overrun) noexcept {
  v_target = std::max(v_target, 0.0);
  const double ve = std::clamp(v_end, 0.0, v_target);
  const Kinematics k0{0.0, start.v_mm_s, start.a_mm_s2};
  // The velocity if the acceleration went back to 0 at once.
  const Side up = up_side(l), down = down_side(l);
  const double a0 = start.a_mm_s2;
  const double v_nat = a0 > 0.0   ? start.v_mm_s + a0 * a0 / (2.0 * up.j_out)
                       : a0 < 0.0 ? start.v_mm_s - a0 * a0 / (2.0 * down.j_out)
                                  : start.v_mm_s;
  const double v_lo = v_nat <= ve ? std::max(v_nat, 0.0) : ve;
  if (peak_distance(k0, v_lo, ve, l) > length_mm) {
    if (allow_overrun) {
      plan.reset(start, l.sin2);
      plan.append_change(ve, l);
      return BlockPlanKind::overrun;
    }
    // Shorter ramps until the stop fits (a step profile at the limit).
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < kBisections; ++i) {
      const double mid = (lo + hi) / 2.0;
      (peak_distance(k0, v_lo, ve, with_ramps_scaled(l, mid)) <= length_mm ? lo : hi) = mid;
    }
    const JerkLimits ls = with_ramps_scaled(l, lo);
    build(plan, start, v_lo, ve, length_mm, ls);
    return BlockPlanKind::forced;
  }
  double v_peak = v_target;
  if (peak_distance(k0, v_target, ve, l) > length_mm) {
    // An acceleration under way carries the speed up to v_nat whatever
    // comes next: a peak below it only adds a pause at that speed on the
    // way down (more distance, not less), so the distance grows with the
    // peak only from v_nat on. Search there, or stay at v_lo's plan (which
    // passes v_nat without a pause) when the peak cannot rise above it.
    // (Braking under way: the distance grows with the peak throughout.)
    double lo = a0 > 0.0 ? std::max(v_lo, std::min(v_nat, v_target)) : v_lo, hi = v_target;
    if (lo > v_lo && peak_distance(k0, lo, ve, l) > length_mm) lo = hi = v_lo;
    for (int i = 0; i < kBisections && hi - lo > kTinyVel; ++i) {
      const double mid = (lo + hi) / 2.0;
      (peak_distance(k0, mid, ve, l) <= length_mm ? lo : hi) = mid;
    }
    v_peak = lo;
  }
  build(plan, start, v_peak, ve, length_mm, l);
  return BlockPlanKind::fits;
}

double jerk_entry_velocity(double length_mm, double v_exit, const JerkLimits& l) noexcept {
  v_exit = std::max(v_exit, 0.0);
  if (!(length_mm > 0.0) || !valid(l)) return v_exit;
  // Above v_exit the braking distance grows without bound: find where it
  // passes the length (doubling, then bisection).
  double lo = v_exit, hi = std::max(v_exit, 1.0);
  while (change_distance(hi, 0.0, v_exit, l) <= length_mm && hi < 1e12) {
    lo = hi;
    hi *= 2.0;
  }
  for (int i = 0; i < kBisections && hi - lo > kTinyVel * std::max(1.0, hi); ++i) {
    const double mid = (lo + hi) / 2.0;
    (change_distance(mid, 0.0, v_exit, l) <= length_mm ? lo : hi) = mid;
  }
  return lo;
}

double jerk_duration_estimate(double length_mm, double v_cmd, const JerkLimits& l) noexcept {
  if (!(length_mm > 0.0)) return 0.0;
  if (!valid(l) || !positive_finite(v_cmd)) return kInf;
  JerkPlan p;
  plan_block(p, Kinematics{}, length_mm, v_cmd, 0.0, l, false);
  return p.duration();
}

}  // namespace nck::motion
