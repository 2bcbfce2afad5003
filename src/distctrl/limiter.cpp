#include "nck/distctrl/limiter.hpp"

#include <algorithm>
#include <cmath>

namespace nck::distctrl {

double Limiter::accel_for(double dist_error_mm) const noexcept {
  if (!s_.adaptive) return s_.a_max_mm_s2;
  const double e = std::fabs(dist_error_mm);
  if (e <= s_.err_a_min_mm) return s_.a_min_mm_s2;
  if (e >= s_.err_a_max_mm) return s_.a_max_mm_s2;
  const double share = (e - s_.err_a_min_mm) / (s_.err_a_max_mm - s_.err_a_min_mm);
  return s_.a_min_mm_s2 + share * (s_.a_max_mm_s2 - s_.a_min_mm_s2);
}

double Limiter::step(double target_mm, double dist_error_mm) noexcept {
  const double d = target_mm - pos_mm_;
  const bool down = d < 0;
  const double v_lim = s_.v_max_mm_s * (down && s_.v_weight_down > 0 ? s_.v_weight_down : 1.0);
  double a = accel_for(dist_error_mm);
  if (down && s_.a_weight_down > 0) a *= s_.a_weight_down;
  // The fastest velocity from which the offset can still stop at the
  // target in whole cycles (k cycles of braking by a*dt travel
  // a*dt^2*k(k+1)/2), capped by v_max and by reaching it within this cycle.
  const double dist = std::fabs(d);
  const double step = a * dt_s_ * dt_s_;
  const double v_brake = step > 0 ? a * dt_s_ * (std::sqrt(0.25 + 2.0 * dist / step) - 0.5) : 0.0;
  const double v_abs = std::min({dist / dt_s_, v_lim, v_brake});
  const double v_want = down ? -v_abs : v_abs;
  const double dv = a * dt_s_;
  v_mm_s_ += std::clamp(v_want - v_mm_s_, -dv, dv);
  pos_mm_ += v_mm_s_ * dt_s_;
  return pos_mm_;
}

}  // namespace nck::distctrl
