#pragma once
// The geometry of one motion block in axis space: a straight line over all
// axes, or a circular arc in a plane with the other changing axes moving
// linearly along (helix). Built at setup time (may fail, returns the cause);
// evaluated in the cyclic path (noexcept, no allocation).
//
// Parametrisation: by path length s in [0, length()]. point_at(length())
// returns the programmed end point exactly, so the path ends where the
// program says, bit for bit.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <expected>
#include <optional>
#include <string_view>

#include "nck/motion/axis_vector.hpp"

namespace nck::motion {

// Why a segment could not be built. The kernel maps these to diagnostics
// (full_circle_with_radius is TF5200 error 20034).
enum class ArcError : std::uint8_t {
  invalid_axis_count,       // n_axes is 0 or greater than kMaxAxes
  plane_axis_out_of_range,  // plane axis index >= n_axes
  plane_axes_equal,         // both plane axes are the same axis
  non_finite_input,         // NaN or infinity in a coordinate, radius or centre
  start_on_center,          // start point is the centre: radius 0
  end_point_not_on_circle,  // start and end radius differ by more than the tolerance
  full_circle_with_radius,  // start == end programmed with R (no unique circle)
  radius_too_small,         // |R| smaller than half the chord
  zero_radius,              // R = 0
};

// A short English description of the cause, for diagnostics.
std::string_view describe(ArcError e) noexcept;

// parabola: a corner blend (docs/decisions.md, "Continuous path and corner
// blending"), the quadratic Bezier start -> control point -> end in the plane,
// run at a uniform Bezier parameter per unit of "path length" s: at a constant
// path speed every axis accelerates constantly. Its length() is the sum of its
// two (equal) legs, so s is not the arc length: the path speed is the true
// speed at both ends and up to cos(turn/2) below it inside.
// cubic: one span of the curvature-continuous path a programmed polyline is
// smoothed into under a jerk-limited slope (docs/decisions.md, "Smoothing
// fine chords"): the cubic Bezier start -> P1 -> P2 -> end in up to three
// axes (the others stand), P1 and P2 at the thirds of the programmed chord.
// s maps to the Bezier parameter through a cubic whose slopes at both ends
// make s the arc length there (segment_cubic.cpp).
enum class SegmentKind : std::uint8_t { line, arc, parabola, cubic };

// How far the start and end radius of a centre-programmed arc may differ:
// accepted when |r_end - r_start| <= max(abs_mm, rel * r_start).
struct ArcTolerance {
  double abs_mm = 0.01;
  double rel = 1e-4;
};

// A segment without its start point: how the command queue carries a
// motion, since each starts where the motion before it ended (the start
// would be stored twice). Segment::tail() and Segment::joined() convert
// without computing anything, so the joined segment is bit for bit the one
// that was planned.
struct SegmentTail {
  SegmentKind kind = SegmentKind::line;
  std::uint8_t n_axes = 0;
  std::uint8_t plane_a = 0, plane_b = 1;
  std::uint8_t axis_c = 0;  // cubic: its third axis (plane_a, plane_b, axis_c)
  AxisVector end{};
  double length_mm = 0;
  // arc only (a parabola: its control point in center_a/center_b; a cubic:
  // P1 in center_a, center_b, r_start_mm and P2 in r_end_mm, angle_start_rad,
  // sweep_rad, for its axes plane_a, plane_b, axis_c)
  double center_a = 0, center_b = 0;
  double r_start_mm = 0, r_end_mm = 0;
  double angle_start_rad = 0, sweep_rad = 0, plane_len_mm = 0;
};

// A cubic span's axes and inner control points (make_cubic).
struct CubicControl {
  std::array<std::size_t, 3> axis{};  // distinct moving axes, or the last repeated
  std::array<double, 3> p1{}, p2{};   // P1 and P2 on them
};

class Segment {
 public:
  Segment() = default;  // an empty line of length 0 with no axes

  // The segment without its start, and back (SegmentTail). rt
  SegmentTail tail() const noexcept;
  static Segment joined(const AxisVector& start, const SegmentTail& t) noexcept;

  SegmentKind kind() const noexcept { return kind_; }
  std::size_t axis_count() const noexcept { return n_axes_; }
  const AxisVector& start_point() const noexcept { return start_; }
  const AxisVector& end_point() const noexcept { return end_; }

  // Path length (mm): Euclidean over the axes that count (see make_line);
  // for an arc sqrt(plane_arc^2 + sum of counted tracking-axis deltas^2).
  double length() const noexcept { return length_mm_; }

  // Position at path length s (clamped to [0, length()]). Axes >= axis_count()
  // are left untouched in out. rt
  void point_at(double s_mm, AxisVector& out) const noexcept;

  // The part of the segment beyond path length s (block search: the rest
  // of a block already partly covered): same path, same parametrisation,
  // starting at point_at(s). setup
  Segment remainder(double s_mm) const noexcept;

  // d(position)/ds at s: the per-axis share of the path velocity. A unit
  // vector over the counted axes; axis velocity = tangent[i] * v_path. rt
  void tangent_at(double s_mm, AxisVector& out) const noexcept;

  // Arc data (meaningless for a line). "ccw" is positive rotation from
  // plane axis a towards plane axis b (G17: a=X b=Y; G18: a=Z b=X; G19: a=Y b=Z).
  std::size_t plane_a() const noexcept { return plane_a_; }
  std::size_t plane_b() const noexcept { return plane_b_; }
  double center_a() const noexcept { return center_a_; }
  double center_b() const noexcept { return center_b_; }
  double radius_start() const noexcept { return r_start_mm_; }
  double radius_end() const noexcept { return r_end_mm_; }
  double sweep_rad() const noexcept { return sweep_rad_; }  // signed, + = ccw
  double plane_arc_length() const noexcept { return plane_len_mm_; }
  // Parabola: its control point in the plane (the legs' intersection).
  double control_a() const noexcept { return center_a_; }
  double control_b() const noexcept { return center_b_; }
  // Cubic: its axes (k = 0..2; repeated when fewer move) and inner control
  // points on them.
  std::size_t cubic_axis(std::size_t k) const noexcept { return k == 0 ? plane_a_ : k == 1 ? plane_b_ : axis_c_; }
  double cubic_p1(std::size_t k) const noexcept { return k == 0 ? center_a_ : k == 1 ? center_b_ : r_start_mm_; }
  double cubic_p2(std::size_t k) const noexcept { return k == 0 ? r_end_mm_ : k == 1 ? angle_start_rad_ : sweep_rad_; }
  // Whether cubic_axis(k) repeats an earlier one (fewer than three move).
  bool cubic_axis_repeats(std::size_t k) const noexcept {
    return (k > 0 && cubic_axis(k) == cubic_axis(0)) || (k > 1 && cubic_axis(k) == cubic_axis(1));
  }
  // Cubic: the length of the vector with component of_axis(k) on each of
  // its distinct axes k (a repeated axis counts once).
  template <class OfAxis>
  double cubic_norm(OfAxis of_axis) const noexcept {
    double sq = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      if (cubic_axis_repeats(k)) continue;
      const double x = of_axis(k);
      sq += x * x;
    }
    return std::sqrt(sq);
  }

 private:
  friend std::expected<Segment, ArcError> make_line(const AxisVector&, const AxisVector&,
                                                    std::size_t, AxisMask) noexcept;
  friend std::expected<Segment, ArcError> make_arc_center(const AxisVector&, const AxisVector&,
                                                          std::size_t, std::size_t, std::size_t,
                                                          double, double, bool, int, ArcTolerance,
                                                          AxisMask) noexcept;
  friend std::expected<Segment, ArcError> make_parabola(const AxisVector&, double, double, const AxisVector&,
                                                        std::size_t, std::size_t, std::size_t) noexcept;
  friend std::optional<Segment> make_cubic(const AxisVector&, const CubicControl&, const AxisVector&,
                                           std::size_t) noexcept;

  double fraction(double s_mm) const noexcept;
  // point_at's plane axes on a parabola at fraction f (kept out of point_at).
  [[gnu::noinline]] void parabola_point(double f, AxisVector& out) const noexcept;
  // A cubic's Bezier parameter at fraction f, and its slope du/df.
  double cubic_parameter(double f, double* slope) const noexcept;
  [[gnu::noinline]] void cubic_point(double f, AxisVector& out) const noexcept;
  void cubic_tangent(double f, AxisVector& out) const noexcept;
  Segment cubic_remainder(double f) const noexcept;

  SegmentKind kind_ = SegmentKind::line;
  std::uint8_t axis_c_ = 0;  // cubic: its third axis
  std::size_t n_axes_ = 0;
  AxisVector start_{};
  AxisVector end_{};
  double length_mm_ = 0.0;
  // arc only
  std::size_t plane_a_ = 0;
  std::size_t plane_b_ = 1;
  double center_a_ = 0.0;
  double center_b_ = 0.0;
  double r_start_mm_ = 0.0;
  double r_end_mm_ = 0.0;  // the arc blends linearly from r_start to r_end
  double angle_start_rad_ = 0.0;
  double sweep_rad_ = 0.0;
  double plane_len_mm_ = 0.0;
};

// Straight line. Only axes in length_axes count for the path length (so F
// can refer to the main axes while a rotary axis follows); if none of those
// moves, all moving axes count. setup
std::expected<Segment, ArcError> make_line(const AxisVector& start, const AxisVector& end,
                                           std::size_t n_axes,
                                           AxisMask length_axes = kAllAxes) noexcept;

// Arc around an absolute centre (the caller resolves I/J/K, G161/G162).
// start == end in the plane gives a full circle; extra_turns adds full turns.
// Every other axis that changes moves linearly (helix). setup
std::expected<Segment, ArcError> make_arc_center(const AxisVector& start, const AxisVector& end,
                                                 std::size_t n_axes, std::size_t plane_a,
                                                 std::size_t plane_b, double center_a,
                                                 double center_b, bool ccw, int extra_turns = 0,
                                                 ArcTolerance tol = {},
                                                 AxisMask length_axes = kAllAxes) noexcept;

// Arc by radius: R > 0 the shorter arc, R < 0 the longer one. A full circle
// cannot be given by R; |R| below half the chord is an error (a radius short by
// no more than the tolerance is taken as a half circle). setup
std::expected<Segment, ArcError> make_arc_radius(const AxisVector& start, const AxisVector& end,
                                                 std::size_t n_axes, std::size_t plane_a,
                                                 std::size_t plane_b, double radius_mm, bool ccw,
                                                 ArcTolerance tol = {},
                                                 AxisMask length_axes = kAllAxes) noexcept;

// A parabola from start to end in the plane (plane_a, plane_b) with its
// control point (control_a, control_b): both legs (start to control point,
// control point to end) should be of one length, so that the path speed is
// the true speed at both ends; every other axis must stand. setup
std::expected<Segment, ArcError> make_parabola(const AxisVector& start, double control_a, double control_b,
                                               const AxisVector& end, std::size_t n_axes, std::size_t plane_a,
                                               std::size_t plane_b) noexcept;

// A cubic span from start to end with the inner control points c (every
// axis not in c.axis must stand). nullopt on a NaN or where its speed law
// would stray more than 2 % from the arc length inside (the caller keeps
// the sharp corner). setup
std::optional<Segment> make_cubic(const AxisVector& start, const CubicControl& c, const AxisVector& end,
                                            std::size_t n_axes) noexcept;

}  // namespace nck::motion
