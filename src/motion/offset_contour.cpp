#include "nck/motion/offset_contour.hpp"

#include <cmath>
#include <numbers>

namespace nck::motion::trc {
namespace {

constexpr double kEps = 1e-9;
constexpr double kTwoPi = 2 * std::numbers::pi;

Vec2 unit(Vec2 p) {
  const double l = length(p);
  return l > kEps ? (1.0 / l) * p : Vec2{};
}

// The offset element: a line through q along t, or a circle (c, r).
struct Offset {
  bool circle = false;
  Vec2 q, t;  // line
  Vec2 c;     // circle
  double r = 0;
};

Offset offset_of(const Element& e, double o) {
  if (e.arc) return {true, {}, {}, e.center, offset_radius(e, o)};
  return {false, offset_start(e, o), tangent_start(e), {}, 0};
}

// Up to two intersection points of two offset elements.
struct Hits {
  int n = 0;
  Vec2 p[2];
  void add(Vec2 v) { p[n++] = v; }
};

void line_circle(const Offset& l, const Offset& c, Hits& h) {
  const Vec2 f = l.q - c.c;
  const double bh = dot(f, l.t);
  const double disc = bh * bh - (dot(f, f) - c.r * c.r);
  if (disc < -kEps) return;
  const double root = std::sqrt(std::max(disc, 0.0));
  h.add(l.q + (-bh - root) * l.t);
  h.add(l.q + (-bh + root) * l.t);
}

Hits intersect(const Offset& x, const Offset& y) {
  Hits h;
  if (!x.circle && !y.circle) {
    const double den = cross(x.t, y.t);
    if (std::abs(den) < kEps) return h;
    h.add(x.q + (cross(y.q - x.q, y.t) / den) * x.t);
  } else if (!x.circle || !y.circle) {
    line_circle(x.circle ? y : x, x.circle ? x : y, h);
  } else {
    const Vec2 d = y.c - x.c;
    const double dist = length(d);
    if (dist < kEps || dist > x.r + y.r + kEps || dist < std::abs(x.r - y.r) - kEps) return h;
    const double along = (x.r * x.r - y.r * y.r + dist * dist) / (2 * dist);
    const double across = std::sqrt(std::max(x.r * x.r - along * along, 0.0));
    const Vec2 u = (1.0 / dist) * d;
    const Vec2 m = x.c + along * u;
    h.add(m + across * left_of(u));
    h.add(m - across * left_of(u));
  }
  return h;
}

double angle_of(Vec2 c, Vec2 p) { return std::atan2(p.b - c.b, p.a - c.a); }

// The whole line or circle a piece lies on.
Offset carrier_of(const Element& e) {
  if (e.arc) return {true, {}, {}, e.center, arc_radius(e)};
  return {false, e.start, unit(e.end - e.start), {}, 0};
}

}  // namespace

double length(Vec2 p) { return std::hypot(p.a, p.b); }

double arc_radius(const Element& e) { return length(e.start - e.center); }

Vec2 tangent_start(const Element& e) {
  if (!e.arc) return unit(e.end - e.start);
  const Vec2 radial = unit(e.start - e.center);
  return e.ccw ? left_of(radial) : -1.0 * left_of(radial);
}

Vec2 tangent_end(const Element& e) {
  if (!e.arc) return unit(e.end - e.start);
  const Vec2 radial = unit(e.end - e.center);
  return e.ccw ? left_of(radial) : -1.0 * left_of(radial);
}

// Moving counter-clockwise the centre lies to the left: a left offset (o > 0)
// brings the tool nearer to it.
double offset_radius(const Element& e, double o) { return arc_radius(e) - (e.ccw ? o : -o); }

Vec2 offset_start(const Element& e, double o) { return e.start + o * left_of(tangent_start(e)); }
Vec2 offset_end(const Element& e, double o) { return e.end + o * left_of(tangent_end(e)); }

Corner corner(const Element& a, const Element& b, double o) {
  Corner k;
  k.center = a.end;
  k.end_a = offset_end(a, o);
  k.start_b = offset_start(b, o);
  const Vec2 ta = tangent_end(a), tb = tangent_start(b);
  const double turn = cross(ta, tb);
  if (o == 0 || (std::abs(turn) < 1e-9 && dot(ta, tb) > 0)) return k;  // smooth
  if (turn * o < 0 || std::abs(turn) < 1e-9) {
    // The tool is on the outer side of the turn (a reversal counts as outer):
    // it rolls about the programmed corner, keeping its distance.
    k.kind = CornerKind::outside;
    k.arc_ccw = o < 0;
    return k;
  }
  k.kind = CornerKind::inside;
  const Hits h = intersect(offset_of(a, o), offset_of(b, o));
  if (h.n == 0) {
    k.error = CornerError::no_intersection;
    return k;
  }
  // Of two candidates the one next to the corner belongs to it.
  Vec2 best = h.p[0];
  if (h.n == 2 && length(h.p[1] - a.end) < length(best - a.end)) best = h.p[1];
  k.end_a = k.start_b = best;
  return k;
}

LinearCorner linear_corner(Vec2 end_a, Vec2 ta, Vec2 start_b, Vec2 tb, double r) {
  LinearCorner lc;
  const double den = cross(ta, tb);
  if (dot(ta, tb) >= 0 && std::abs(den) > kEps) {
    // end_a + s ta = start_b - u tb
    const double s = cross(start_b - end_a, tb) / den;
    lc.n = 1;
    lc.p[0] = end_a + s * ta;
    return lc;
  }
  lc.n = 2;
  lc.p[0] = end_a + r * ta;
  lc.p[1] = start_b - r * tb;
  return lc;
}

double sweep_rad(Vec2 c, Vec2 s, Vec2 e, bool ccw) {
  double d = ccw ? angle_of(c, e) - angle_of(c, s) : angle_of(c, s) - angle_of(c, e);
  while (d <= 1e-12) d += kTwoPi;
  while (d > kTwoPi) d -= kTwoPi;
  return d;
}

namespace {

constexpr double kEndMm = 1e-6;

bool degenerate(const Element& e) { return e.arc ? arc_radius(e) < kEps : length(e.end - e.start) < kEps; }

// p lies on e's carrier: is it inside e, away from its ends?
bool inside_piece(const Element& e, Vec2 p) {
  if (length(p - e.start) < kEndMm || length(p - e.end) < kEndMm) return false;
  if (!e.arc) {
    const double along = dot(p - e.start, unit(e.end - e.start));
    return along > 0 && along < length(e.end - e.start);
  }
  return sweep_rad(e.center, e.start, p, e.ccw) < sweep_rad(e.center, e.start, e.end, e.ccw);
}

}  // namespace

bool pieces_cross(const Element& p, const Element& q) {
  if (degenerate(p) || degenerate(q)) return false;
  const Hits h = intersect(carrier_of(p), carrier_of(q));
  // Two equal points: the pieces touch (a slot exactly as wide as the tool), no crossing.
  if (h.n == 2 && length(h.p[0] - h.p[1]) < kEndMm) return false;
  for (int i = 0; i < h.n; ++i)
    if (inside_piece(p, h.p[i]) && inside_piece(q, h.p[i])) return true;
  return false;
}

bool keeps_direction(const Element& p, Vec2 s, Vec2 e) {
  if (length(e - s) < 1e-9) return true;  // the element shrinks to a point: nothing to cut
  if (!p.arc) return dot(e - s, p.end - p.start) > 0;
  return sweep_rad(p.center, s, e, p.ccw) <= sweep_rad(p.center, p.start, p.end, p.ccw) + 1e-7;
}

}  // namespace nck::motion::trc
