#include "nck/prep/blend_limits.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace nck::prep {
namespace {

// The set points are exact on the path, but a cycle that speeds up on an arc
// turns by its mean speed: 1 % of a_max is left for that.
constexpr double kCapShare = 0.99;
// Speeding up or braking on a fillet: this share of the feed acceleration.
constexpr double kFilletTangentialShare = 0.25;
// On a parabola: it is run at one speed (a feedhold or an override change
// on it is the only change), and every share taken from its turn costs
// speed where the time is lost (docs/performance.md, issue 30).
constexpr double kParabolaTangentialShare = 0.05;

struct PlaneBudget {
  double a_feed_mm_s2 = 0;  // the smaller feed acceleration (speeding up or braking) of both plane axes
  double a_cap_mm_s2 = 0;   // what their vector sum may reach
  double v_max_mm_s = 0;    // the smaller vb of both
};

PlaneBudget plane_budget(const motion::Segment& arc, const BlendDynamics& d) {
  const std::size_t a = arc.plane_a(), b = arc.plane_b();
  const motion::AxisDynamics& da = d.feed[a];
  const motion::AxisDynamics& db = d.feed[b];
  PlaneBudget p;
  p.a_feed_mm_s2 = std::min({da.a_acc_mm_s2, da.a_dec_mm_s2, db.a_acc_mm_s2, db.a_dec_mm_s2});
  p.a_cap_mm_s2 = kCapShare * std::min(d.a_max_mm_s2[a], d.a_max_mm_s2[b]);
  p.v_max_mm_s = std::min(da.v_max_mm_s, db.v_max_mm_s);
  return p;
}

// What the vector sum leaves for the along-path part beside a_n.
double along_beside(double a_cap_mm_s2, double a_n_mm_s2) {
  return a_n_mm_s2 < a_cap_mm_s2 ? std::sqrt(a_cap_mm_s2 * a_cap_mm_s2 - a_n_mm_s2 * a_n_mm_s2) : 0.0;
}

// The cycle that crosses from a blend into the next block (or back) lies on
// both: its chord leans by e (v sin e = across * dt) against the block's
// tangent and, as a chord of the blend, is shorter than the path it covers
// (by theta^2/24 at most, theta the blend's turn in the step): the step's
// along-path change is up to v (1 - cos e + theta^2/24) / dt more than the
// speed-up. across: the acceleration across the path in that step.
double crossing_chord_excess(double v_mm_s, double across_mm_s2, double theta, double cycle_s) {
  const double lean = std::min(across_mm_s2 * cycle_s / std::max(v_mm_s, 1e-9), 1.0);
  return v_mm_s * (1 - std::sqrt(1 - lean * lean) + theta * theta / 24) / cycle_s;
}

// The plane axes' acceleration on parabola p at path speed 1 mm/s (signed,
// mm/s^2 per (mm/s)^2): constant over it, 2 (p0 - 2 c + p2) / length^2.
std::array<double, 2> parabola_turn(const motion::Segment& p) {
  const double k = 2.0 / (p.length() * p.length());
  const std::size_t a = p.plane_a(), b = p.plane_b();
  return {k * (p.start_point()[a] - 2.0 * p.control_a() + p.end_point()[a]),
          k * (p.start_point()[b] - 2.0 * p.control_b() + p.end_point()[b])};
}

}  // namespace

motion::PathLimits parabola_limits(const motion::Segment& parabola, const BlendDynamics& d) {
  const PlaneBudget p = plane_budget(parabola, d);
  const double a_t = kParabolaTangentialShare * p.a_feed_mm_s2;
  const std::array<double, 2> turn = parabola_turn(parabola);
  const std::array<std::size_t, 2> axis{parabola.plane_a(), parabola.plane_b()};
  // Each axis on its own: its turn and (at most, the tangent's share being
  // at most 1) the along-path part within its own a_max.
  double v2 = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 2; ++k) {
    const double left = kCapShare * d.a_max_mm_s2[axis[k]] - a_t;
    if (std::fabs(turn[k]) > 0) v2 = std::min(v2, std::max(left, 0.0) / std::fabs(turn[k]));
  }
  motion::PathLimits l;
  l.v_max_mm_s = std::min(p.v_max_mm_s, std::sqrt(v2));
  l.a_acc_mm_s2 = l.a_dec_mm_s2 = a_t;
  return l;
}

double parabola_pass_acceleration(const motion::Segment& parabola, const motion::PathLimits& parabola_l,
                                  const motion::Segment& other, const motion::PathLimits& other_l, bool other_after,
                                  const BlendDynamics& d, double cycle_s) {
  const double v = parabola_l.v_max_mm_s;
  const std::array<double, 2> turn = parabola_turn(parabola);
  const std::array<std::size_t, 2> axis{parabola.plane_a(), parabola.plane_b()};
  // Half the parabola's acceleration (what the crossing chord lies on it)
  // plus the other block's own turn one step faster, per axis, signed.
  std::array<double, 2> across{0.5 * turn[0] * v * v, 0.5 * turn[1] * v * v};
  const motion::AxisVector& joint = other_after ? other.start_point() : other.end_point();
  if (other.kind() == motion::SegmentKind::arc) {
    const double v1 = v + std::max(other_l.a_acc_mm_s2, other_l.a_dec_mm_s2) * cycle_s;
    const double r = std::min(other.radius_start(), other.radius_end());
    const double to_a = other.center_a() - joint[axis[0]], to_b = other.center_b() - joint[axis[1]];
    const double k = v1 * v1 / (r * std::max(std::hypot(to_a, to_b), 1e-12));
    across[0] += k * to_a;
    across[1] += k * to_b;
  }
  motion::AxisVector t{};
  other.tangent_at(other_after ? 0.0 : other.length(), t);
  double a = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 2; ++k) {
    const double left = kCapShare * d.a_max_mm_s2[axis[k]] - std::fabs(across[k]);
    if (left <= 0) return 0.0;
    if (std::fabs(t[axis[k]]) > 1e-12) a = std::min(a, left / std::fabs(t[axis[k]]));
  }
  const double a_turn = std::hypot(turn[0], turn[1]) * v * v;
  const double extra =
      crossing_chord_excess(v, std::hypot(across[0], across[1]), a_turn * cycle_s / std::max(v, 1e-9), cycle_s);
  return std::isfinite(a) ? std::max(a - extra, 0.0) : 0.0;
}

motion::PathLimits fillet_limits(const motion::Segment& fillet, const BlendDynamics& d, double feed_mm_s) {
  const PlaneBudget p = plane_budget(fillet, d);
  const double r = std::min(fillet.radius_start(), fillet.radius_end());
  const double a_share = std::min(kFilletTangentialShare * p.a_feed_mm_s2, p.a_cap_mm_s2);
  // 1 % above the feed: rounding must not leave the fillet a hair slower
  const double v_mm_s = 1.01 * feed_mm_s;
  const double a_beside_feed = std::min(p.a_feed_mm_s2, along_beside(p.a_cap_mm_s2, v_mm_s * v_mm_s / r));
  const double a_t = std::max(a_share, a_beside_feed);
  const double a_n = along_beside(p.a_cap_mm_s2, a_t);
  motion::PathLimits l;
  l.v_max_mm_s = std::min(p.v_max_mm_s, std::sqrt(a_n * r));
  l.a_acc_mm_s2 = l.a_dec_mm_s2 = a_t;
  return l;
}

void widen_arc_limits(const motion::Segment& arc, const BlendDynamics& d, bool out_of_fillet, motion::PathLimits& l) {
  if (arc.kind() != motion::SegmentKind::arc || l.slope != SlopeProfile::step) return;
  if (std::fabs(arc.plane_arc_length() - arc.length()) > 1e-9 * arc.length()) return;  // a helix
  const PlaneBudget p = plane_budget(arc, d);
  const double r = std::min(arc.radius_start(), arc.radius_end());
  if (!(r > 0) || !std::isfinite(l.v_max_mm_s)) return;
  const double a_t = std::min(p.a_feed_mm_s2, along_beside(p.a_cap_mm_s2, l.v_max_mm_s * l.v_max_mm_s / r));
  double& raised = out_of_fillet ? l.a_acc_mm_s2 : l.a_dec_mm_s2;
  raised = std::max(raised, a_t);
}

double pass_acceleration(const motion::Segment& fillet, const motion::PathLimits& fillet_l,
                         const motion::Segment& next, const motion::PathLimits& next_l, const BlendDynamics& d,
                         double cycle_s) {
  const PlaneBudget p = plane_budget(fillet, d);
  const double v = fillet_l.v_max_mm_s, r = std::min(fillet.radius_start(), fillet.radius_end());
  double across = 0.5 * v * v / r;
  if (next.kind() == motion::SegmentKind::arc) {
    const double v1 = v + std::max(next_l.a_acc_mm_s2, next_l.a_dec_mm_s2) * cycle_s;
    across += v1 * v1 / std::min(next.radius_start(), next.radius_end());
  }
  // what the crossing chord adds: about 160 mm/s^2 at 8.7 mm/s on a 0.026 mm fillet
  const double extra = crossing_chord_excess(v, across, v * cycle_s / r, cycle_s);
  return std::max(along_beside(p.a_cap_mm_s2, across) - extra, 0.0);
}

}  // namespace nck::prep
