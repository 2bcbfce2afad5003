#include "nck/motion/junction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "nck/motion/path_profile.hpp"

namespace nck::motion {
namespace {

// Direction changes below this (about 1e-9 rad) are rounding, not corners.
constexpr double kStraight = 1e-9;

}  // namespace

double corner_velocity(const AxisVector& t_in, const AxisVector& t_out, std::span<const double> dv_mm_s) noexcept {
  double v = std::numeric_limits<double>::infinity();
  const std::size_t n = std::min(dv_mm_s.size(), t_in.size());
  for (std::size_t j = 0; j < n; ++j) {
    const double turn = std::fabs(t_out[j] - t_in[j]);
    if (turn <= kStraight) continue;
    v = std::min(v, std::max(dv_mm_s[j], 0.0) / turn);
  }
  return v;
}

double transition_velocity(const AxisVector& t_in, const AxisVector& t_out, std::span<const double> dv_mm_s,
                           double braking_step_mm_s, double cruise_in_mm_s, double cruise_out_mm_s) noexcept {
  const double corner = corner_velocity(t_in, t_out, dv_mm_s) - braking_step_mm_s;
  return std::max(std::min({corner, cruise_in_mm_s, cruise_out_mm_s}), 0.0);
}

double entry_velocity_limit(double length_mm, double v_exit_mm_s, double a_dec_mm_s2, double dt_s) noexcept {
  // The profile holds v_exit over its last cycles: entering at v_exit is
  // always possible.
  const double beyond_mm = pass_brake_distance(v_exit_mm_s, a_dec_mm_s2, dt_s);
  return std::max(discrete_brake_velocity(length_mm + beyond_mm, a_dec_mm_s2, dt_s), v_exit_mm_s);
}

}  // namespace nck::motion
