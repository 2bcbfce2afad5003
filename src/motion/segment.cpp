#include "nck/motion/segment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace nck::motion {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Start and end closer than this in the plane are "the same point": a full circle.
constexpr double kSamePointMm = 1e-6;

bool all_finite(const AxisVector& v, std::size_t n) noexcept {
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}

// Sum of squared deltas of the axes selected by `use`, skipping the plane axes
// of an arc (skip_a/skip_b = kMaxAxes for none).
double sum_sq(const AxisVector& a, const AxisVector& b, std::size_t n, AxisMask use,
              std::size_t skip_a, std::size_t skip_b) noexcept {
  double acc = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i == skip_a || i == skip_b || !in_mask(use, i)) continue;
    const double d = b[i] - a[i];
    acc += d * d;
  }
  return acc;
}

}  // namespace

std::string_view describe(ArcError e) noexcept {
  switch (e) {
    case ArcError::invalid_axis_count: return "axis count is 0 or above the channel maximum";
    case ArcError::plane_axis_out_of_range: return "circle plane axis is not a channel axis";
    case ArcError::plane_axes_equal: return "circle plane needs two different axes";
    case ArcError::non_finite_input: return "coordinate, centre or radius is not a finite number";
    case ArcError::start_on_center: return "circle start point lies on the centre (radius 0)";
    case ArcError::end_point_not_on_circle: return "end point not on circle: start and end radius differ";
    case ArcError::full_circle_with_radius: return "a full circle cannot be programmed with R";
    case ArcError::radius_too_small: return "radius smaller than half the distance from start to end";
    case ArcError::zero_radius: return "radius R is 0";
  }
  return "unknown arc error";
}

SegmentTail Segment::tail() const noexcept {
  SegmentTail t;
  t.kind = kind_;
  t.n_axes = static_cast<std::uint8_t>(n_axes_);
  t.plane_a = static_cast<std::uint8_t>(plane_a_);
  t.plane_b = static_cast<std::uint8_t>(plane_b_);
  t.axis_c = axis_c_;
  t.end = end_;
  t.length_mm = length_mm_;
  t.center_a = center_a_;
  t.center_b = center_b_;
  t.r_start_mm = r_start_mm_;
  t.r_end_mm = r_end_mm_;
  t.angle_start_rad = angle_start_rad_;
  t.sweep_rad = sweep_rad_;
  t.plane_len_mm = plane_len_mm_;
  return t;
}

Segment Segment::joined(const AxisVector& start, const SegmentTail& t) noexcept {
  Segment s;
  s.kind_ = t.kind;
  s.n_axes_ = t.n_axes;
  s.plane_a_ = t.plane_a;
  s.plane_b_ = t.plane_b;
  s.axis_c_ = t.axis_c;
  s.start_ = start;
  s.end_ = t.end;
  s.length_mm_ = t.length_mm;
  s.center_a_ = t.center_a;
  s.center_b_ = t.center_b;
  s.r_start_mm_ = t.r_start_mm;
  s.r_end_mm_ = t.r_end_mm;
  s.angle_start_rad_ = t.angle_start_rad;
  s.sweep_rad_ = t.sweep_rad;
  s.plane_len_mm_ = t.plane_len_mm;
  return s;
}

double Segment::fraction(double s_mm) const noexcept {
  if (!(length_mm_ > 0.0)) return 1.0;
  if (!(s_mm > 0.0)) return 0.0;  // also catches NaN
  if (s_mm >= length_mm_) return 1.0;
  return s_mm / length_mm_;
}

void Segment::point_at(double s_mm, AxisVector& out) const noexcept {
  const double f = fraction(s_mm);
  if (f >= 1.0) {  // exact end point: no rounding drift at the block end
    std::copy_n(end_.begin(), n_axes_, out.begin());
    return;
  }
  for (std::size_t i = 0; i < n_axes_; ++i) out[i] = start_[i] + f * (end_[i] - start_[i]);
  // A line returns after one test of its kind (as before parabolas; the
  // kind is now held in a register for the second test: one instruction
  // more), and the parabola's point is out of line.
  if (kind_ == SegmentKind::line) [[likely]] return;
  if (kind_ == SegmentKind::parabola) [[unlikely]] return parabola_point(f, out);
  if (kind_ == SegmentKind::cubic) [[unlikely]] return cubic_point(f, out);
  const double ang = angle_start_rad_ + f * sweep_rad_;
  const double r = r_start_mm_ + f * (r_end_mm_ - r_start_mm_);
  out[plane_a_] = center_a_ + r * std::cos(ang);
  out[plane_b_] = center_b_ + r * std::sin(ang);
}

void Segment::parabola_point(double f, AxisVector& out) const noexcept {
  const double g = 1.0 - f;
  out[plane_a_] = g * g * start_[plane_a_] + 2.0 * f * g * center_a_ + f * f * end_[plane_a_];
  out[plane_b_] = g * g * start_[plane_b_] + 2.0 * f * g * center_b_ + f * f * end_[plane_b_];
}

Segment Segment::remainder(double s_mm) const noexcept {
  const double f = fraction(s_mm);
  if (kind_ == SegmentKind::cubic) return cubic_remainder(f);
  Segment r = *this;
  point_at(s_mm, r.start_);
  r.length_mm_ = length_mm_ * (1.0 - f);
  if (kind_ == SegmentKind::parabola) {  // de Casteljau: the same curve, the same speed law
    r.center_a_ = (1.0 - f) * center_a_ + f * end_[plane_a_];
    r.center_b_ = (1.0 - f) * center_b_ + f * end_[plane_b_];
    r.plane_len_mm_ = r.length_mm_;
  } else if (kind_ == SegmentKind::arc) {
    r.angle_start_rad_ = angle_start_rad_ + f * sweep_rad_;
    r.sweep_rad_ = sweep_rad_ * (1.0 - f);
    r.r_start_mm_ = r_start_mm_ + f * (r_end_mm_ - r_start_mm_);
    r.plane_len_mm_ = plane_len_mm_ * (1.0 - f);
  }
  return r;
}

void Segment::tangent_at(double s_mm, AxisVector& out) const noexcept {
  if (!(length_mm_ > 0.0)) {
    std::fill_n(out.begin(), n_axes_, 0.0);
    return;
  }
  for (std::size_t i = 0; i < n_axes_; ++i) out[i] = (end_[i] - start_[i]) / length_mm_;
  if (kind_ == SegmentKind::cubic) [[unlikely]] {
    cubic_tangent(fraction(s_mm), out);
  } else if (kind_ == SegmentKind::parabola) [[unlikely]] {  // not a unit vector inside: the axes' share of the path speed
    const double f = fraction(s_mm), k = 2.0 / length_mm_;
    out[plane_a_] = k * ((1.0 - f) * (center_a_ - start_[plane_a_]) + f * (end_[plane_a_] - center_a_));
    out[plane_b_] = k * ((1.0 - f) * (center_b_ - start_[plane_b_]) + f * (end_[plane_b_] - center_b_));
  } else if (kind_ == SegmentKind::arc) {
    const double f = fraction(s_mm);
    const double ang = angle_start_rad_ + f * sweep_rad_;
    const double r = r_start_mm_ + f * (r_end_mm_ - r_start_mm_);
    const double dang_ds = sweep_rad_ / length_mm_;
    const double dr_ds = (r_end_mm_ - r_start_mm_) / length_mm_;
    out[plane_a_] = dr_ds * std::cos(ang) - r * std::sin(ang) * dang_ds;
    out[plane_b_] = dr_ds * std::sin(ang) + r * std::cos(ang) * dang_ds;
  }
}

std::expected<Segment, ArcError> make_line(const AxisVector& start, const AxisVector& end,
                                           std::size_t n_axes, AxisMask length_axes) noexcept {
  if (n_axes == 0 || n_axes > kMaxAxes) return std::unexpected(ArcError::invalid_axis_count);
  if (!all_finite(start, n_axes) || !all_finite(end, n_axes)) {
    return std::unexpected(ArcError::non_finite_input);
  }
  Segment seg;
  seg.kind_ = SegmentKind::line;
  seg.n_axes_ = n_axes;
  seg.start_ = start;
  seg.end_ = end;
  double sq = sum_sq(start, end, n_axes, length_axes, kMaxAxes, kMaxAxes);
  if (sq == 0.0) sq = sum_sq(start, end, n_axes, kAllAxes, kMaxAxes, kMaxAxes);
  seg.length_mm_ = std::sqrt(sq);
  return seg;
}

namespace {

// Signed sweep from angle a0 to a1 in the requested direction, in (0, 2pi]
// (or [-2pi, 0) for cw); a full circle when start and end coincide.
double sweep_between(double a0, double a1, bool ccw, bool full) noexcept {
  if (full) return ccw ? kTwoPi : -kTwoPi;
  double d = a1 - a0;
  if (ccw) {
    while (d <= 0.0) d += kTwoPi;
    while (d > kTwoPi) d -= kTwoPi;
  } else {
    while (d >= 0.0) d -= kTwoPi;
    while (d < -kTwoPi) d += kTwoPi;
  }
  return d;
}

}  // namespace

namespace {
// The axis count and plane axes an arc needs, or what is wrong with them.
std::optional<ArcError> plane_error(std::size_t n_axes, std::size_t plane_a,
                                    std::size_t plane_b) noexcept {
  if (n_axes == 0 || n_axes > kMaxAxes) return ArcError::invalid_axis_count;
  if (plane_a >= n_axes || plane_b >= n_axes) return ArcError::plane_axis_out_of_range;
  if (plane_a == plane_b) return ArcError::plane_axes_equal;
  return std::nullopt;
}
}  // namespace

std::expected<Segment, ArcError> make_arc_center(const AxisVector& start, const AxisVector& end,
                                                 std::size_t n_axes, std::size_t plane_a,
                                                 std::size_t plane_b, double center_a,
                                                 double center_b, bool ccw, int extra_turns,
                                                 ArcTolerance tol,
                                                 AxisMask length_axes) noexcept {
  if (auto e = plane_error(n_axes, plane_a, plane_b)) return std::unexpected(*e);
  if (!all_finite(start, n_axes) || !all_finite(end, n_axes) || !std::isfinite(center_a) ||
      !std::isfinite(center_b)) {
    return std::unexpected(ArcError::non_finite_input);
  }
  const double sa = start[plane_a] - center_a, sb = start[plane_b] - center_b;
  const double ea = end[plane_a] - center_a, eb = end[plane_b] - center_b;
  const double r0 = std::hypot(sa, sb);
  const double r1 = std::hypot(ea, eb);
  if (!(r0 > kSamePointMm)) return std::unexpected(ArcError::start_on_center);
  if (std::abs(r1 - r0) > std::max(tol.abs_mm, tol.rel * r0)) {
    return std::unexpected(ArcError::end_point_not_on_circle);
  }
  const bool full = std::hypot(ea - sa, eb - sb) < kSamePointMm;
  const double a0 = std::atan2(sb, sa);
  double sweep = sweep_between(a0, std::atan2(eb, ea), ccw, full);
  const double turns = static_cast<double>(std::max(extra_turns, 0));
  sweep += (ccw ? kTwoPi : -kTwoPi) * turns;

  Segment seg;
  seg.kind_ = SegmentKind::arc;
  seg.n_axes_ = n_axes;
  seg.start_ = start;
  seg.end_ = end;
  seg.plane_a_ = plane_a;
  seg.plane_b_ = plane_b;
  seg.center_a_ = center_a;
  seg.center_b_ = center_b;
  seg.r_start_mm_ = r0;
  seg.r_end_mm_ = r1;
  seg.angle_start_rad_ = a0;
  seg.sweep_rad_ = sweep;
  // Mean radius: exact for a circle, within (r1-r0)^2 for the tolerated spiral.
  seg.plane_len_mm_ = std::abs(sweep) * 0.5 * (r0 + r1);
  const double track_sq = sum_sq(start, end, n_axes, length_axes, plane_a, plane_b);
  seg.length_mm_ = std::sqrt(seg.plane_len_mm_ * seg.plane_len_mm_ + track_sq);
  return seg;
}

std::expected<Segment, ArcError> make_arc_radius(const AxisVector& start, const AxisVector& end,
                                                 std::size_t n_axes, std::size_t plane_a,
                                                 std::size_t plane_b, double radius_mm, bool ccw,
                                                 ArcTolerance tol,
                                                 AxisMask length_axes) noexcept {
  if (auto e = plane_error(n_axes, plane_a, plane_b)) return std::unexpected(*e);
  if (!std::isfinite(radius_mm) || !std::isfinite(start[plane_a]) ||
      !std::isfinite(start[plane_b]) || !std::isfinite(end[plane_a]) ||
      !std::isfinite(end[plane_b])) {
    return std::unexpected(ArcError::non_finite_input);
  }
  if (radius_mm == 0.0) return std::unexpected(ArcError::zero_radius);
  const double da = end[plane_a] - start[plane_a];
  const double db = end[plane_b] - start[plane_b];
  const double chord = std::hypot(da, db);
  if (chord < kSamePointMm) return std::unexpected(ArcError::full_circle_with_radius);
  const double r = std::abs(radius_mm);
  const double half = 0.5 * chord;
  if (r < half - std::max(tol.abs_mm, tol.rel * r)) {
    return std::unexpected(ArcError::radius_too_small);
  }
  // Centre on the perpendicular bisector; for the short ccw arc it lies to
  // the left of the chord direction, each flip (cw, long arc) changes side.
  const double h = std::sqrt(std::max(r * r - half * half, 0.0));
  const double side = (ccw ? 1.0 : -1.0) * (radius_mm > 0.0 ? 1.0 : -1.0);
  const double left_a = -db / chord, left_b = da / chord;
  const double ca = start[plane_a] + 0.5 * da + side * h * left_a;
  const double cb = start[plane_b] + 0.5 * db + side * h * left_b;
  // The computed centre is equidistant by construction (a radius that was
  // short by the tolerance gives a half circle of radius chord/2).
  return make_arc_center(start, end, n_axes, plane_a, plane_b, ca, cb, ccw, 0, tol, length_axes);
}

std::expected<Segment, ArcError> make_parabola(const AxisVector& start, double control_a, double control_b,
                                               const AxisVector& end, std::size_t n_axes, std::size_t plane_a,
                                               std::size_t plane_b) noexcept {
  if (auto e = plane_error(n_axes, plane_a, plane_b)) return std::unexpected(*e);
  if (!all_finite(start, n_axes) || !all_finite(end, n_axes) || !std::isfinite(control_a) ||
      !std::isfinite(control_b))
    return std::unexpected(ArcError::non_finite_input);
  Segment seg;
  seg.kind_ = SegmentKind::parabola;
  seg.n_axes_ = n_axes;
  seg.start_ = start;
  seg.end_ = end;
  seg.plane_a_ = plane_a;
  seg.plane_b_ = plane_b;
  seg.center_a_ = control_a;
  seg.center_b_ = control_b;
  const double leg1 = std::hypot(control_a - start[plane_a], control_b - start[plane_b]);
  const double leg2 = std::hypot(end[plane_a] - control_a, end[plane_b] - control_b);
  seg.length_mm_ = seg.plane_len_mm_ = leg1 + leg2;
  return seg;
}

}  // namespace nck::motion
