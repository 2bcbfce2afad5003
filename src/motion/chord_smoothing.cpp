#include "nck/motion/chord_smoothing.hpp"

#include <cmath>

namespace nck::motion {
namespace {

constexpr double kStill = 1e-12;  // mm: an axis that moves less stands

// The programmed start of a chord: a line's start, or a span's, from its
// inner control points at the thirds (P1 - (P2 - P1)).
AxisVector chord_start(const Segment& s) {
  AxisVector v = s.start_point();
  if (s.kind() == SegmentKind::cubic)
    for (std::size_t k = 0; k < 3; ++k) v[s.cubic_axis(k)] = 2.0 * s.cubic_p1(k) - s.cubic_p2(k);
  return v;
}

// Whether the line's length counts every moving axis (a rotary axis that
// F does not refer to would make the spline's arc length a different measure).
bool counts_every_axis(const Segment& line) {
  double sq = 0;
  for (std::size_t i = 0; i < line.axis_count(); ++i) {
    const double d = line.end_point()[i] - line.start_point()[i];
    sq += d * d;
  }
  return std::fabs(std::sqrt(sq) - line.length()) <= 1e-9 * line.length();
}

// The span over chord a -> b from `from` to `to`.
std::optional<Segment> span(const AxisVector& from, const AxisVector& a, const AxisVector& b, const AxisVector& to,
                            const CubicControl& axes, std::size_t n_axes) {
  CubicControl c = axes;
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t i = c.axis[k];
    c.p1[k] = a[i] + (b[i] - a[i]) / 3.0;
    c.p2[k] = a[i] + 2.0 * (b[i] - a[i]) / 3.0;
  }
  return make_cubic(from, c, to, n_axes);
}

}  // namespace

std::optional<SmoothedVertex> smooth_vertex(const Segment& before, const Segment& after, double path_dev_mm) noexcept {
  const std::size_t n = before.axis_count();
  if (!(path_dev_mm > 0) || n != after.axis_count() || after.kind() != SegmentKind::line) return std::nullopt;
  if (before.kind() != SegmentKind::line && before.kind() != SegmentKind::cubic) return std::nullopt;
  if (!counts_every_axis(after) || (before.kind() == SegmentKind::line && !counts_every_axis(before)))
    return std::nullopt;
  const AxisVector v_start = chord_start(before), &v = before.end_point(), &v_end = after.end_point();
  CubicControl axes;
  std::size_t moving = 0;
  AxisVector smoothed = v;
  double dev_sq = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::fabs(v[i] - v_start[i]) <= kStill && std::fabs(v_end[i] - v[i]) <= kStill) continue;
    if (moving == 3) return std::nullopt;  // a spline in more than three axes: not here
    axes.axis[moving++] = i;
    const double e = (v_start[i] - 2.0 * v[i] + v_end[i]) / 6.0;
    smoothed[i] = v[i] + e;
    dev_sq += e * e;
  }
  if (moving < 2 || std::sqrt(dev_sq) > path_dev_mm || !(dev_sq > 0)) return std::nullopt;
  for (std::size_t k = moving; k < 3; ++k) axes.axis[k] = axes.axis[moving - 1];
  auto b = span(before.start_point(), v_start, v, smoothed, axes, n);
  auto a = span(smoothed, v, v_end, v_end, axes, n);
  if (!b || !a) return std::nullopt;
  return SmoothedVertex{*b, *a, std::sqrt(dev_sq)};
}

}  // namespace nck::motion
