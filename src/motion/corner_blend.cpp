#include "nck/motion/corner_blend.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "corner_geometry.hpp"

namespace nck::motion {
namespace {

using namespace corner_geometry;

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

std::optional<CornerBlend> blend_corner(const Segment& a, const Segment& b, const BlendBounds& bounds) noexcept {
  const double path_dev_mm = bounds.path_dev_mm;
  const auto c = corner_between(a, b, path_dev_mm);
  if (!c) return std::nullopt;
  const Curve &in = c->in, &out = c->out;
  const V2 corner = c->at;
  const double turn = c->turn;
  // Collinear or tangent: nothing to blend; a reversal has no fillet.
  if (std::fabs(turn) < 1e-6 || std::fabs(turn) > std::numbers::pi - 1e-3) return std::nullopt;
  const bool left = turn > 0;
  auto ok = [&](double r) -> std::optional<Fillet> {
    auto fl = fillet_at(in, out, corner, left, r);
    if (!fl || fl->deviation > path_dev_mm || fl->deviation < -kTiny) return std::nullopt;
    if (!(fl->trim1 > kTiny && fl->trim1 <= bounds.max_trim_a_mm)) return std::nullopt;
    if (!(fl->trim2 > kTiny && fl->trim2 <= bounds.max_trim_b_mm)) return std::nullopt;
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
  // A smaller radius deviates less and trims less: it passes too.
  if (bounds.size_share < 1) lo *= bounds.size_share;
  std::optional<Fillet> fl;
  if (lo > 0) fl = ok(lo);
  if (!fl) return std::nullopt;

  const auto sides = trimmed_blocks(a, b, *c, fl->t1, fl->t2);
  if (!sides) return std::nullopt;
  auto fillet = make_arc_center(sides->t1, sides->t2, a.axis_count(), c->plane.a, c->plane.b, fl->f.x, fl->f.y, left);
  if (!fillet) return std::nullopt;
  CornerBlend cb{sides->before, *fillet, sides->after, lo, fl->deviation, 0};
  cb.shortfall_mm = std::max(fl->trim1 + fl->trim2 - fillet->length(), 0.0);
  return cb;
}

}  // namespace nck::motion
