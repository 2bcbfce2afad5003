#include "nck/motion/corner_blend.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace nck::motion {
namespace {

struct V2 {
  double x = 0, y = 0;
};
V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.y + b.y}; }
V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.y - b.y}; }
V2 operator*(double k, V2 a) { return {k * a.x, k * a.y}; }
double dot(V2 a, V2 b) { return a.x * b.x + a.y * b.y; }
double cross(V2 a, V2 b) { return a.x * b.y - a.y * b.x; }
double norm(V2 a) { return std::hypot(a.x, a.y); }
V2 left_normal(V2 t) { return {-t.y, t.x}; }
// Angle from u to w, counter-clockwise positive, in (-pi, pi].
double angle_between(V2 u, V2 w) { return std::atan2(cross(u, w), dot(u, w)); }

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

V2 in_plane(const AxisVector& v, Plane pl) { return {v[pl.a], v[pl.b]}; }

// The two axes the corner lies in (an arc's plane, else the axes the lines
// move), when every other axis stands still over both blocks.
std::optional<Plane> corner_plane(const Segment& s1, const Segment& s2) {
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
std::optional<Curve> curve_of(const Segment& s, Plane pl, bool at_end) {
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
V2 tangent(const Curve& c, V2 x) {
  if (!c.arc) return c.t;
  const V2 radial = x - c.p;
  const V2 t = (1.0 / norm(radial)) * left_normal(radial);
  return c.ccw ? t : -1.0 * t;
}

// Intersections of the offsets: each candidate centre is handed to take().
template <class F>
void line_line(V2 p1, V2 t1, V2 p2, V2 t2, F take) {
  const double d = cross(t1, t2);
  if (std::fabs(d) < 1e-12) return;
  take(p1 + (cross(p2 - p1, t2) / d) * t1);
}
template <class F>
void line_circle(V2 p, V2 t, V2 c, double rho, F take) {
  const V2 w = p - c;
  const double b = dot(t, w), disc = b * b - (dot(w, w) - rho * rho);
  if (disc < 0) return;
  const double s = std::sqrt(disc);
  take(p + (-b - s) * t);
  take(p + (-b + s) * t);
}
template <class F>
void circle_circle(V2 c1, double r1, V2 c2, double r2, F take) {
  const V2 d = c2 - c1;
  const double dist = norm(d);
  if (dist < kTiny) return;
  const double a = (dist * dist + r1 * r1 - r2 * r2) / (2 * dist), h2 = r1 * r1 - a * a;
  if (h2 < 0) return;
  const V2 u = (1.0 / dist) * d, mid = c1 + a * u, off = std::sqrt(h2) * left_normal(u);
  take(mid + off);
  take(mid - off);
}

// The fillet of radius r in the corner P turning left or right.
struct Fillet {
  V2 f{}, t1{}, t2{};
  double trim1 = 0, trim2 = 0, sweep = 0, deviation = 0;
};

// Where the fillet touches curve c (centre f, radius r).
V2 touch_point(const Curve& c, V2 f, double r, double side) {
  if (!c.arc) return f - (side * r) * left_normal(c.t);
  return c.p + (c.r / norm(f - c.p)) * (f - c.p);
}

// Path length from x to y along c in its direction (arcs: the short way in
// its sense, negative when y lies behind x).
double along(const Curve& c, V2 x, V2 y) {
  if (!c.arc) return dot(y - x, c.t);
  const double ang = angle_between(x - c.p, y - c.p);
  return c.r * (c.ccw ? ang : -ang);
}

std::optional<Fillet> fillet_at(const Curve& in, const Curve& out, V2 corner, bool left, double r) {
  const double side = left ? 1.0 : -1.0;
  // Offsets of both curves by r towards the inside of the turn.
  auto offset_radius = [&](const Curve& c) { return (left == c.ccw) ? c.r - r : c.r + r; };
  if ((in.arc && offset_radius(in) <= kTiny) || (out.arc && offset_radius(out) <= kTiny)) return std::nullopt;
  std::optional<V2> best;
  auto take = [&](V2 f) {
    if (!best || norm(f - corner) < norm(*best - corner)) best = f;
  };
  const V2 shift_in = (side * r) * left_normal(in.t), shift_out = (side * r) * left_normal(out.t);
  if (!in.arc && !out.arc) line_line(in.p + shift_in, in.t, out.p + shift_out, out.t, take);
  else if (!in.arc) line_circle(in.p + shift_in, in.t, out.p, offset_radius(out), take);
  else if (!out.arc) line_circle(out.p + shift_out, out.t, in.p, offset_radius(in), take);
  else circle_circle(in.p, offset_radius(in), out.p, offset_radius(out), take);
  if (!best) return std::nullopt;
  Fillet fl;
  fl.f = *best;
  fl.t1 = touch_point(in, fl.f, r, side);
  fl.t2 = touch_point(out, fl.f, r, side);
  fl.trim1 = along(in, fl.t1, corner);
  fl.trim2 = along(out, corner, fl.t2);
  const double sweep = angle_between(fl.t1 - fl.f, fl.t2 - fl.f);
  fl.sweep = left ? sweep : -sweep;
  fl.deviation = norm(corner - fl.f) - r;
  return fl;
}

}  // namespace

std::optional<CornerBlend> blend_corner(const Segment& a, const Segment& b, double path_dev_mm,
                                        double max_trim_a_mm, double max_trim_b_mm) noexcept {
  if (!(path_dev_mm > 0) || !std::isfinite(path_dev_mm)) return std::nullopt;
  const auto pl = corner_plane(a, b);
  if (!pl) return std::nullopt;
  const auto in = curve_of(a, *pl, true), out = curve_of(b, *pl, false);
  if (!in || !out) return std::nullopt;
  const V2 corner = in_plane(a.end_point(), *pl);
  if (norm(corner - in_plane(b.start_point(), *pl)) > kTiny) return std::nullopt;
  const V2 t_in = tangent(*in, corner), t_out = tangent(*out, corner);
  const double turn = angle_between(t_in, t_out);
  // Collinear or tangent: nothing to blend; a reversal has no fillet.
  if (std::fabs(turn) < 1e-6 || std::fabs(turn) > std::numbers::pi - 1e-3) return std::nullopt;
  const bool left = turn > 0;
  auto ok = [&](double r) -> std::optional<Fillet> {
    auto fl = fillet_at(*in, *out, corner, left, r);
    if (!fl || fl->deviation > path_dev_mm || fl->deviation < -kTiny) return std::nullopt;
    if (!(fl->trim1 > kTiny && fl->trim1 <= max_trim_a_mm)) return std::nullopt;
    if (!(fl->trim2 > kTiny && fl->trim2 <= max_trim_b_mm)) return std::nullopt;
    if (!(fl->sweep > 0 && fl->sweep < std::numbers::pi)) return std::nullopt;
    return fl;
  };
  // The largest radius that passes: double while it does, then bisect.
  // Between two arcs bending the same way a gentle kink may allow any
  // radius (the fillet tends to their common tangent): past kMaxRadiusMm it
  // is straight for every feed and still computes exactly.
  double lo = 0, hi = path_dev_mm;
  if (ok(hi)) {
    while (2 * hi <= kMaxRadiusMm && ok(2 * hi)) hi *= 2;
    lo = hi;
    hi = std::min(2 * hi, kMaxRadiusMm);
  }
  for (int i = 0; i < 50; ++i) {
    const double mid = (lo + hi) / 2;
    (ok(mid) ? lo : hi) = mid;
  }
  std::optional<Fillet> fl;
  if (lo > 0) fl = ok(lo);
  if (!fl) return std::nullopt;

  auto full = [&](V2 p) {
    AxisVector v = a.end_point();
    v[pl->a] = p.x;
    v[pl->b] = p.y;
    return v;
  };
  const std::size_t n = a.axis_count();
  const AxisVector p1 = full(fl->t1), p2 = full(fl->t2);
  auto before = in->arc ? make_arc_center(a.start_point(), p1, n, pl->a, pl->b, in->p.x, in->p.y, in->ccw)
                        : make_line(a.start_point(), p1, n);
  auto after = out->arc ? make_arc_center(p2, b.end_point(), n, pl->a, pl->b, out->p.x, out->p.y, out->ccw)
                        : make_line(p2, b.end_point(), n);
  auto fillet = make_arc_center(p1, p2, n, pl->a, pl->b, fl->f.x, fl->f.y, left);
  if (!before || !after || !fillet) return std::nullopt;
  CornerBlend cb{*before, *fillet, *after, lo, fl->deviation, 0};
  cb.shortfall_mm = std::max(fl->trim1 + fl->trim2 - fillet->length(), 0.0);
  return cb;
}

namespace {

// A parabola in the corner: start, control point, end, the trims of both
// blocks (path length) and the corner's distance from it.
struct Bezier {
  V2 p0{}, c{}, p2{};
  double trim1 = 0, trim2 = 0, deviation = 0;
};

V2 rotated(V2 p, V2 centre, double ang) {
  const double co = std::cos(ang), si = std::sin(ang);
  const V2 d = p - centre;
  return centre + V2{co * d.x - si * d.y, si * d.x + co * d.y};
}

// The point of c at path length tau after (ahead) or before the corner.
V2 point_from(const Curve& c, V2 corner, double tau, bool ahead) {
  const double dir = ahead ? 1.0 : -1.0;
  if (!c.arc) return corner + (dir * tau) * c.t;
  return rotated(corner, c.p, dir * (c.ccw ? tau : -tau) / c.r);
}

V2 bezier_at(const Bezier& z, double u) {
  const double g = 1 - u;
  return (g * g) * z.p0 + (2 * u * g) * z.c + (u * u) * z.p2;
}

// The distance of x from the curve: sampled, then refined around the nearest sample.
double distance_to(const Bezier& z, V2 x) {
  constexpr int kSamples = 64;
  int best = 0;
  double d_best = norm(z.p0 - x);
  for (int i = 1; i <= kSamples; ++i) {
    const double d = norm(bezier_at(z, static_cast<double>(i) / kSamples) - x);
    if (d < d_best) d_best = d, best = i;
  }
  double lo = std::max(best - 1, 0) / double(kSamples), hi = std::min(best + 1, kSamples) / double(kSamples);
  for (int i = 0; i < 60; ++i) {  // ternary search on a unimodal piece
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (norm(bezier_at(z, m1) - x) < norm(bezier_at(z, m2) - x)) hi = m2;
    else lo = m1;
  }
  return std::min(d_best, norm(bezier_at(z, (lo + hi) / 2) - x));
}

double bezier_length(const Bezier& z) {
  constexpr int kSamples = 256;
  double len = 0;
  V2 last = z.p0;
  for (int i = 1; i <= kSamples; ++i) {
    const V2 p = bezier_at(z, static_cast<double>(i) / kSamples);
    len += norm(p - last);
    last = p;
  }
  return len;
}

// Where the lines p1 + s t1 and p2 + w t2 meet.
std::optional<V2> meet(V2 p1, V2 t1, V2 p2, V2 t2) {
  const double d = cross(t1, t2);
  if (std::fabs(d) < 1e-12) return std::nullopt;
  return p1 + (cross(p2 - p1, t2) / d) * t1;
}

// The parabola whose arc end lies tau from the corner (between lines: both
// legs tau); the line's end follows from the equal legs.
std::optional<Bezier> parabola_at(const Curve& in, const Curve& out, V2 corner, double tau) {
  Bezier z;
  if (!in.arc && !out.arc) {
    z = {corner - tau * in.t, corner, corner + tau * out.t, tau, tau, 0};
  } else if (!in.arc) {
    z.p2 = point_from(out, corner, tau, true);
    const V2 t2 = tangent(out, z.p2);
    const auto c = meet(corner, in.t, z.p2, t2);
    if (!c || dot(z.p2 - *c, t2) <= 0) return std::nullopt;
    z.c = *c;
    z.p0 = z.c - norm(z.p2 - z.c) * in.t;
    z.trim1 = dot(corner - z.p0, in.t);
    z.trim2 = tau;
  } else if (!out.arc) {
    z.p0 = point_from(in, corner, tau, false);
    const V2 t1 = tangent(in, z.p0);
    const auto c = meet(z.p0, t1, corner, out.t);
    if (!c || dot(*c - z.p0, t1) <= 0) return std::nullopt;
    z.c = *c;
    z.p2 = z.c + norm(z.c - z.p0) * out.t;
    z.trim1 = tau;
    z.trim2 = dot(z.p2 - corner, out.t);
  } else {
    return std::nullopt;  // arc-arc: the fillet
  }
  z.deviation = distance_to(z, corner);
  return z;
}

}  // namespace

std::optional<CornerBlend> blend_corner_parabola(const Segment& a, const Segment& b, double path_dev_mm,
                                                 double max_trim_a_mm, double max_trim_b_mm) noexcept {
  if (!(path_dev_mm > 0) || !std::isfinite(path_dev_mm)) return std::nullopt;
  const auto pl = corner_plane(a, b);
  if (!pl) return std::nullopt;
  const auto in = curve_of(a, *pl, true), out = curve_of(b, *pl, false);
  if (!in || !out || (in->arc && out->arc)) return std::nullopt;
  const V2 corner = in_plane(a.end_point(), *pl);
  if (norm(corner - in_plane(b.start_point(), *pl)) > kTiny) return std::nullopt;
  const double turn = angle_between(tangent(*in, corner), tangent(*out, corner));
  // Up to 150 degrees: beyond, the parabola's legs grow long against its
  // deviation and it turns slower than a fillet.
  if (std::fabs(turn) < 1e-6 || std::fabs(turn) > 150.0 / 180.0 * std::numbers::pi) return std::nullopt;
  auto ok = [&](double tau) -> std::optional<Bezier> {
    auto z = parabola_at(*in, *out, corner, tau);
    if (!z || z->deviation > path_dev_mm) return std::nullopt;
    if (!(z->trim1 > kTiny && z->trim1 <= max_trim_a_mm)) return std::nullopt;
    if (!(z->trim2 > kTiny && z->trim2 <= max_trim_b_mm)) return std::nullopt;
    return z;
  };
  // The parameter runs along the arc (or both lines): at most its trim bound.
  double hi = in->arc ? max_trim_a_mm : out->arc ? max_trim_b_mm : std::min(max_trim_a_mm, max_trim_b_mm);
  double lo = 0;
  if (ok(hi)) {
    lo = hi;
  } else {
    for (int i = 0; i < 50; ++i) {
      const double mid = (lo + hi) / 2;
      (ok(mid) ? lo : hi) = mid;
    }
  }
  std::optional<Bezier> z;
  if (lo > 0) z = ok(lo);
  if (!z) return std::nullopt;

  auto full = [&](V2 p) {
    AxisVector v = a.end_point();
    v[pl->a] = p.x;
    v[pl->b] = p.y;
    return v;
  };
  const std::size_t n = a.axis_count();
  const AxisVector p0 = full(z->p0), p2 = full(z->p2);
  auto before = in->arc ? make_arc_center(a.start_point(), p0, n, pl->a, pl->b, in->p.x, in->p.y, in->ccw)
                        : make_line(a.start_point(), p0, n);
  auto after = out->arc ? make_arc_center(p2, b.end_point(), n, pl->a, pl->b, out->p.x, out->p.y, out->ccw)
                        : make_line(p2, b.end_point(), n);
  auto blend = make_parabola(p0, z->c.x, z->c.y, p2, n, pl->a, pl->b);
  if (!before || !after || !blend) return std::nullopt;
  CornerBlend cb{*before, *blend, *after, 0.5 * blend->length(), z->deviation, 0};
  cb.shortfall_mm = std::max(z->trim1 + z->trim2 - bezier_length(*z), 0.0);
  return cb;
}

}  // namespace nck::motion
