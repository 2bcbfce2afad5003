#pragma once
// The plane geometry both corner blends share (corner_blend.cpp: fillets,
// corner_parabola.cpp: parabolas): 2-D vectors, the two blocks near the
// corner as a line or a circle, the plane they lie in. Internal to
// src/motion; setup side.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "nck/motion/segment.hpp"

namespace nck::motion::corner_geometry {

struct V2 {
  double x = 0, y = 0;
};
inline V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.y + b.y}; }
inline V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.y - b.y}; }
inline V2 operator*(double k, V2 a) { return {k * a.x, k * a.y}; }
inline double dot(V2 a, V2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(V2 a, V2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(V2 a) { return std::hypot(a.x, a.y); }
inline V2 left_normal(V2 t) { return {-t.y, t.x}; }
// Angle from u to w, counter-clockwise positive, in (-pi, pi].
inline double angle_between(V2 u, V2 w) { return std::atan2(cross(u, w), dot(u, w)); }

// Coordinates below this (1 nm) are rounding; radii may differ by 1 % at
// most for an arc to count as a circle here (the decoder accepts centre
// programming with a small end-radius error).
constexpr double kTiny = 1e-9;
constexpr double kRadiusSpread = 0.01;
constexpr double kMaxRadiusMm = 1e4;

// One block near the corner, in the plane: a line through p along t, or a
// circle around p of radius r run ccw or cw.
struct Curve {
  bool arc = false;
  V2 p{}, t{};
  double r = 0;
  bool ccw = false;
};

struct Plane {
  std::size_t a = 0, b = 1;
};

inline V2 in_plane(const AxisVector& v, Plane pl) { return {v[pl.a], v[pl.b]}; }

// The two axes the corner lies in (an arc's plane, else the axes the lines
// move), when every other axis stands still over both blocks.
inline std::optional<Plane> corner_plane(const Segment& s1, const Segment& s2) {
  const std::size_t n = s1.axis_count();
  if (n != s2.axis_count() || n < 2) return std::nullopt;
  std::optional<Plane> pl;
  for (const Segment* s : {&s1, &s2})
    if (s->kind() == SegmentKind::arc) {
      const Plane p{s->plane_a(), s->plane_b()};
      if (pl && (pl->a != p.a || pl->b != p.b)) return std::nullopt;
      pl = p;
    }
  if (!pl) {
    std::size_t found[2]{}, count = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const bool moves = std::fabs(s1.end_point()[j] - s1.start_point()[j]) > kTiny ||
                         std::fabs(s2.end_point()[j] - s2.start_point()[j]) > kTiny;
      if (!moves) continue;
      if (count == 2) return std::nullopt;  // a corner in space: not blended
      found[count++] = j;
    }
    if (count != 2) return std::nullopt;
    pl = Plane{found[0], found[1]};
  }
  for (std::size_t j = 0; j < n; ++j) {
    if (j == pl->a || j == pl->b) continue;
    const double z = s1.end_point()[j];
    if (std::fabs(s1.start_point()[j] - z) > kTiny || std::fabs(s2.start_point()[j] - z) > kTiny ||
        std::fabs(s2.end_point()[j] - z) > kTiny)
      return std::nullopt;  // helix or a moving third axis
  }
  return pl;
}

// The curve of s near its end (at_end) or start, or nullopt for an arc
// that is not a plain circle (extra turns, a spiral).
inline std::optional<Curve> curve_of(const Segment& s, Plane pl, bool at_end) {
  Curve c;
  const V2 p0 = in_plane(s.start_point(), pl), p1 = in_plane(s.end_point(), pl);
  if (s.kind() == SegmentKind::line) {
    const double len = norm(p1 - p0);
    if (len <= kTiny) return std::nullopt;
    c.p = at_end ? p1 : p0;
    c.t = (1.0 / len) * (p1 - p0);
    return c;
  }
  const double r0 = s.radius_start(), r1 = s.radius_end();
  if (std::fabs(s.sweep_rad()) >= 2 * std::numbers::pi - 1e-9) return std::nullopt;
  if (std::fabs(r1 - r0) > kRadiusSpread * std::max(r0, r1)) return std::nullopt;
  c.arc = true;
  c.p = {s.center_a(), s.center_b()};
  c.r = at_end ? r1 : r0;
  c.ccw = s.sweep_rad() > 0;
  return c;
}

// Direction of travel of c at point x.
inline V2 tangent(const Curve& c, V2 x) {
  if (!c.arc) return c.t;
  const V2 radial = x - c.p;
  const V2 t = (1.0 / norm(radial)) * left_normal(radial);
  return c.ccw ? t : -1.0 * t;
}

// The corner between a (ending there) and b (starting there) as both
// blends see it: its plane, the two blocks' curves near it, the point and
// the turn (ccw positive). nullopt where there is no corner to blend (no
// usable tolerance, not in one plane, not a plain circle, a gap).
struct Corner {
  Plane plane;
  Curve in, out;
  V2 at;
  double turn = 0;
};
inline std::optional<Corner> corner_between(const Segment& a, const Segment& b, double path_dev_mm) {
  if (!(path_dev_mm > 0) || !std::isfinite(path_dev_mm)) return std::nullopt;
  // Lines and arcs only: a smoothed chord (cubic) or a blend ends its chain.
  for (const Segment* s : {&a, &b})
    if (s->kind() != SegmentKind::line && s->kind() != SegmentKind::arc) return std::nullopt;
  const auto pl = corner_plane(a, b);
  if (!pl) return std::nullopt;
  const auto in = curve_of(a, *pl, true), out = curve_of(b, *pl, false);
  if (!in || !out) return std::nullopt;
  const V2 at = in_plane(a.end_point(), *pl);
  if (norm(at - in_plane(b.start_point(), *pl)) > kTiny) return std::nullopt;
  return Corner{*pl, *in, *out, at, angle_between(tangent(*in, at), tangent(*out, at))};
}

// The two blocks trimmed to a blend's tangent points t1 (on a, near its
// end) and t2 (on b, near its start): lines stay lines, arcs stay on their
// circle; the other axes where the corner is.
struct Trimmed {
  Segment before, after;
  AxisVector t1, t2;  // the tangent points in every axis
};
inline std::optional<Trimmed> trimmed_blocks(const Segment& a, const Segment& b, const Corner& c, V2 t1, V2 t2) {
  const Plane pl = c.plane;
  const Curve &in = c.in, &out = c.out;
  auto full = [&](V2 p) {
    AxisVector v = a.end_point();
    v[pl.a] = p.x;
    v[pl.b] = p.y;
    return v;
  };
  const std::size_t n = a.axis_count();
  const AxisVector p1 = full(t1), p2 = full(t2);
  auto before = in.arc ? make_arc_center(a.start_point(), p1, n, pl.a, pl.b, in.p.x, in.p.y, in.ccw)
                       : make_line(a.start_point(), p1, n);
  auto after = out.arc ? make_arc_center(p2, b.end_point(), n, pl.a, pl.b, out.p.x, out.p.y, out.ccw)
                       : make_line(p2, b.end_point(), n);
  if (!before || !after) return std::nullopt;
  return Trimmed{*before, *after, p1, p2};
}

}  // namespace nck::motion::corner_geometry
