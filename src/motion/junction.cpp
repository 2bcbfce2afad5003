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

AxisVector end_curvature(const Segment& seg, bool at_end) noexcept {
  AxisVector k{};
  const double len = seg.length(), h = 1e-3 * len;
  if (seg.kind() == SegmentKind::line || !(h > 0)) return k;
  if (seg.kind() == SegmentKind::arc) {  // towards the centre, 1/r (a helix: its share of the path squared)
    const AxisVector& p = at_end ? seg.end_point() : seg.start_point();
    const double r = at_end ? seg.radius_end() : seg.radius_start();
    const double share = seg.plane_arc_length() / len;
    if (!(r > 0)) return k;
    k[seg.plane_a()] = (seg.center_a() - p[seg.plane_a()]) / (r * r) * share * share;
    k[seg.plane_b()] = (seg.center_b() - p[seg.plane_b()]) / (r * r) * share * share;
    return k;
  }
  AxisVector t0{}, t1{};
  seg.tangent_at(at_end ? len - h : 0.0, t0);
  seg.tangent_at(at_end ? len : h, t1);
  for (std::size_t j = 0; j < seg.axis_count(); ++j) k[j] = (t1[j] - t0[j]) / h;
  return k;
}

double curvature_step_velocity(const AxisVector& t_in, const AxisVector& k_in, const AxisVector& t_out,
                               const AxisVector& k_out, std::span<const double> dv_mm_s, double dt_s) noexcept {
  constexpr double kFlat = 1e-6;  // 1/mm: a radius of a kilometre is a straight line here
  double v = std::numeric_limits<double>::infinity();
  const std::size_t n = std::min(dv_mm_s.size(), t_in.size());
  for (std::size_t j = 0; j < n; ++j) {
    const double bend = std::fabs(k_out[j] - k_in[j]);
    const double turn = std::fabs(t_out[j] - t_in[j]);
    if (bend <= kFlat && turn <= kStraight) continue;
    // bend v^2 + (turn / dt) v = dv / dt: the positive root, written so
    // that bend -> 0 gives the kink's dv / turn.
    const double b = turn / dt_s, c = std::max(dv_mm_s[j], 0.0) / dt_s;
    v = std::min(v, 2 * c / (b + std::sqrt(b * b + 4 * bend * c)));
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
