// The parabolic corner blend (SegmentKind::parabola, docs/decisions.md,
// "Continuous path and corner blending"): a quadratic Bezier with equal legs,
// tangent to both blocks, as large as PATH_DEV and the trims allow. Found in a
// few steps per corner (preparation places one every few blocks of a dense
// program).
#include "nck/motion/corner_blend.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "corner_geometry.hpp"

namespace nck::motion {
namespace {

using namespace corner_geometry;

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

V2 bezier_velocity(const Bezier& z, double u) { return 2.0 * ((1 - u) * (z.c - z.p0) + u * (z.p2 - z.c)); }

// |v| without hypot's care for overflow (slow, and these are millimetres).
double length_of(V2 v) { return std::sqrt(dot(v, v)); }

// The distance of x from the curve: Newton's method on (B(u) - x) . B'(u)
// = 0 from the middle (a corner lies across from it), or an end if nearer.
double distance_to(const Bezier& z, V2 x) {
  const V2 acc = 2.0 * (z.p0 - 2.0 * z.c + z.p2);
  double u = 0.5;
  for (int i = 0; i < 30; ++i) {
    const V2 d = bezier_at(z, u) - x, vel = bezier_velocity(z, u);
    const double slope = dot(vel, vel) + dot(d, acc);
    if (!(slope > 0)) break;
    const double next = std::clamp(u - dot(d, vel) / slope, 0.0, 1.0);
    if (std::fabs(next - u) < 1e-12) break;
    u = next;
  }
  return std::min({length_of(bezier_at(z, u) - x), length_of(z.p0 - x), length_of(z.p2 - x)});
}

// Arc length: Gauss-Legendre, five points on each half (its speed is smooth).
double bezier_length(const Bezier& z) {
  static constexpr std::array<double, 5> kNode{-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                               0.9061798459386640};
  static constexpr std::array<double, 5> kWeight{0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                                 0.4786286704993665, 0.2369268850561891};
  double len = 0;
  for (const double mid : {0.25, 0.75})
    for (std::size_t i = 0; i < kNode.size(); ++i) len += 0.25 * kWeight[i] * length_of(bezier_velocity(z, mid + 0.25 * kNode[i]));
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
    z.p0 = z.c - length_of(z.p2 - z.c) * in.t;
    z.trim1 = dot(corner - z.p0, in.t);
    z.trim2 = tau;
  } else if (!out.arc) {
    z.p0 = point_from(in, corner, tau, false);
    const V2 t1 = tangent(in, z.p0);
    const auto c = meet(z.p0, t1, corner, out.t);
    if (!c || dot(*c - z.p0, t1) <= 0) return std::nullopt;
    z.c = *c;
    z.p2 = z.c + length_of(z.c - z.p0) * out.t;
    z.trim1 = tau;
    z.trim2 = dot(z.p2 - corner, out.t);
  } else {
    return std::nullopt;  // arc-arc: the fillet
  }
  z.deviation = distance_to(z, corner);
  return z;
}

}  // namespace

std::optional<CornerBlend> blend_corner_parabola(const Segment& a, const Segment& b, const BlendBounds& bounds) noexcept {
  const double path_dev_mm = bounds.path_dev_mm, max_trim_a_mm = bounds.max_trim_a_mm, max_trim_b_mm = bounds.max_trim_b_mm;
  const auto c = corner_between(a, b, path_dev_mm);
  if (!c || (c->in.arc && c->out.arc)) return std::nullopt;  // arc-arc: the fillet
  const Curve &in = c->in, &out = c->out;
  const V2 corner = c->at;
  const double turn = c->turn;
  // Up to 150 degrees: beyond, the parabola's legs grow long against its
  // deviation and it turns slower than a fillet.
  if (std::fabs(turn) < 1e-6 || std::fabs(turn) > 150.0 / 180.0 * std::numbers::pi) return std::nullopt;
  auto ok = [&](double tau) -> std::optional<Bezier> {
    auto z = parabola_at(in, out, corner, tau);
    if (!z || z->deviation > path_dev_mm) return std::nullopt;
    if (!(z->trim1 > kTiny && z->trim1 <= max_trim_a_mm)) return std::nullopt;
    if (!(z->trim2 > kTiny && z->trim2 <= max_trim_b_mm)) return std::nullopt;
    return z;
  };
  // The parameter runs along the arc (or both lines): at most its trim bound.
  const double hi = in.arc ? max_trim_a_mm : out.arc ? max_trim_b_mm : std::min(max_trim_a_mm, max_trim_b_mm);
  // The deviation grows about in proportion to the parabola's size (between
  // lines exactly): from the lines' closed form, one proportional step, then
  // the secant (a few steps), then a hair smaller where rounding left it above.
  double tau = std::min(4 * path_dev_mm / norm(tangent(out, corner) - tangent(in, corner)), hi);
  double tau_last = 0, miss_last = -path_dev_mm;  // at tau 0 the deviation is 0
  for (int i = 0; i < 12; ++i) {
    const auto z = parabola_at(in, out, corner, tau);
    if (!z) break;
    const double miss = z->deviation - path_dev_mm;
    if (miss == miss_last) break;
    const double next = std::clamp(tau - miss * (tau - tau_last) / (miss - miss_last), 0.5 * tau, std::min(2 * tau, hi));
    if (std::fabs(next - tau) <= 1e-13 * tau) break;
    tau_last = tau, miss_last = miss, tau = next;
  }
  std::optional<Bezier> z = ok(tau);
  if (!z) z = ok(tau *= 1 - 1e-9);
  if (!z) {  // a trim bound, or steps that did not settle: bisection below
    double lo = 0, up = tau;
    for (int i = 0; i < 50; ++i) {
      const double mid = (lo + up) / 2;
      (ok(mid) ? lo : up) = mid;
    }
    tau = lo;
    if (lo > 0) z = ok(lo);
  }
  // A shorter leg deviates less and trims less: it passes too.
  if (z && bounds.size_share < 1) z = ok(tau * bounds.size_share);
  if (!z) return std::nullopt;

  const auto sides = trimmed_blocks(a, b, *c, z->p0, z->p2);
  if (!sides) return std::nullopt;
  auto blend = make_parabola(sides->t1, z->c.x, z->c.y, sides->t2, a.axis_count(), c->plane.a, c->plane.b);
  if (!blend) return std::nullopt;
  CornerBlend cb{sides->before, *blend, sides->after, 0.5 * blend->length(), z->deviation, 0};
  cb.shortfall_mm = std::max(z->trim1 + z->trim2 - bezier_length(*z), 0.0);
  return cb;
}

}  // namespace nck::motion
