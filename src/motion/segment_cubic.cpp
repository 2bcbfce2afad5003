// The cubic span (SegmentKind::cubic, docs/decisions.md "Smoothing fine
// chords"): a cubic Bezier in up to three axes, run by path length. The
// Bezier parameter u is not the arc length; u = h(f), f = s / length, where
// h is the cubic with h(0) = 0, h(1) = 1 whose slopes at both ends make s
// the arc length there. So the path speed is exact where two spans meet
// (a chain of spans runs without a speed step) and within 2 % inside
// (make_cubic refuses a span that strays further).
#include <cmath>

#include "nck/motion/segment.hpp"

namespace nck::motion {
namespace {

// The speed law may stray this far from the arc length inside a span.
constexpr double kSpeedLawTolerance = 0.02;

struct Bezier {
  double p0, p1, p2, p3;
  double at(double u) const noexcept {
    const double g = 1.0 - u;
    return g * g * g * p0 + 3.0 * g * g * u * p1 + 3.0 * g * u * u * p2 + u * u * u * p3;
  }
  double slope(double u) const noexcept {
    const double g = 1.0 - u;
    return 3.0 * (g * g * (p1 - p0) + 2.0 * g * u * (p2 - p1) + u * u * (p3 - p2));
  }
};

}  // namespace

double Segment::cubic_parameter(double f, double* slope) const noexcept {
  // |B'(0)| = 3 |P1 - P0|, |B'(1)| = 3 |P3 - P2| over the distinct axes.
  const double start_leg = cubic_norm([&](std::size_t k) { return cubic_p1(k) - start_[cubic_axis(k)]; });
  const double end_leg = cubic_norm([&](std::size_t k) { return end_[cubic_axis(k)] - cubic_p2(k); });
  const double h0 = length_mm_ / (3.0 * start_leg), h1 = length_mm_ / (3.0 * end_leg);
  const double g = 1.0 - f;
  // h(f) = f + (h0 - 1) f (1 - f)^2 - (h1 - 1) f^2 (1 - f)
  if (slope) *slope = 1.0 + (h0 - 1.0) * g * (1.0 - 3.0 * f) - (h1 - 1.0) * f * (2.0 - 3.0 * f);
  return f + (h0 - 1.0) * f * g * g - (h1 - 1.0) * f * f * g;
}

void Segment::cubic_point(double f, AxisVector& out) const noexcept {
  const double u = cubic_parameter(f, nullptr);
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t i = cubic_axis(k);
    out[i] = Bezier{start_[i], cubic_p1(k), cubic_p2(k), end_[i]}.at(u);
  }
}

void Segment::cubic_tangent(double f, AxisVector& out) const noexcept {
  double du_df = 0;
  const double u = cubic_parameter(f, &du_df);
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t i = cubic_axis(k);
    out[i] = Bezier{start_[i], cubic_p1(k), cubic_p2(k), end_[i]}.slope(u) * du_df / length_mm_;
  }
}

// The rest beyond fraction f: the Bezier's second part (de Casteljau), run
// with a speed law of its own; a line to the end if that one strays.
Segment Segment::cubic_remainder(double f) const noexcept {
  const double u = cubic_parameter(f, nullptr), g = 1.0 - u;
  AxisVector from{};
  point_at(f * length_mm_, from);
  CubicControl c;
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t i = cubic_axis(k);
    c.axis[k] = i;
    c.p1[k] = g * g * cubic_p1(k) + 2.0 * u * g * cubic_p2(k) + u * u * end_[i];
    c.p2[k] = g * cubic_p2(k) + u * end_[i];
  }
  if (auto r = make_cubic(from, c, end_, n_axes_)) return *r;
  return make_line(from, end_, n_axes_).value_or(Segment{});
}

std::optional<Segment> make_cubic(const AxisVector& start, const CubicControl& c, const AxisVector& end,
                                  std::size_t n_axes) noexcept {
  if (n_axes == 0 || n_axes > kMaxAxes) return std::nullopt;
  auto spline_axis = [&](std::size_t i) { return i == c.axis[0] || i == c.axis[1] || i == c.axis[2]; };
  for (std::size_t i = 0; i < n_axes; ++i) {
    if (!std::isfinite(start[i]) || !std::isfinite(end[i])) return std::nullopt;
    if (!spline_axis(i) && start[i] != end[i]) return std::nullopt;  // only the spline's axes move
  }
  Segment seg;
  seg.kind_ = SegmentKind::cubic;
  seg.n_axes_ = n_axes;
  seg.start_ = start;
  seg.end_ = end;
  seg.plane_a_ = c.axis[0];
  seg.plane_b_ = c.axis[1];
  seg.axis_c_ = static_cast<std::uint8_t>(c.axis[2]);
  seg.center_a_ = c.p1[0], seg.center_b_ = c.p1[1], seg.r_start_mm_ = c.p1[2];
  seg.r_end_mm_ = c.p2[0], seg.angle_start_rad_ = c.p2[1], seg.sweep_rad_ = c.p2[2];
  for (std::size_t k = 0; k < 3; ++k)
    if (c.axis[k] >= n_axes || !std::isfinite(c.p1[k]) || !std::isfinite(c.p2[k])) return std::nullopt;
  // |B'(u)| over the distinct axes.
  auto speed = [&](double u) {
    return seg.cubic_norm([&](std::size_t k) {
      const std::size_t i = c.axis[k];
      return Bezier{start[i], c.p1[k], c.p2[k], end[i]}.slope(u);
    });
  };
  // Arc length: Gauss-Legendre, five points on each half.
  static constexpr double kNode[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                      0.9061798459386640};
  static constexpr double kWeight[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                        0.4786286704993665, 0.2369268850561891};
  double len = 0;
  for (const double mid : {0.25, 0.75})
    for (std::size_t n = 0; n < 5; ++n) len += 0.25 * kWeight[n] * speed(mid + 0.25 * kNode[n]);
  if (!(len > 0) || !(speed(0) > 0) || !(speed(1) > 0)) return std::nullopt;
  seg.length_mm_ = seg.plane_len_mm_ = len;
  for (const double f : {0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875}) {
    double du_df = 0;
    const double u = seg.cubic_parameter(f, &du_df);
    if (std::fabs(speed(u) * du_df / len - 1.0) > kSpeedLawTolerance) return std::nullopt;
  }
  return seg;
}

}  // namespace nck::motion
