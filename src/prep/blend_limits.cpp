#include "nck/prep/blend_limits.hpp"

#include <algorithm>
#include <cmath>

namespace nck::prep {
namespace {

// The set points are exact on the path, but a cycle that speeds up on an arc
// turns by its mean speed: 1 % of a_max is left for that.
constexpr double kCapShare = 0.99;
// Speeding up or braking on a fillet: this share of the feed acceleration.
constexpr double kFilletTangentialShare = 0.25;

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

}  // namespace

motion::PathLimits fillet_limits(const motion::Segment& fillet, const BlendDynamics& d) {
  const PlaneBudget p = plane_budget(fillet, d);
  const double a_t = std::min(kFilletTangentialShare * p.a_feed_mm_s2, p.a_cap_mm_s2);
  const double a_n = along_beside(p.a_cap_mm_s2, a_t);
  const double r = std::min(fillet.radius_start(), fillet.radius_end());
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
  // The crossing chord leans by e (v sin e = across * dt) against the next
  // block's tangent and, as a chord of the fillet, is shorter than the path
  // it covers (by theta^2/24 at most, theta = v dt / r): the step's
  // along-path change is up to v (1 - cos e + theta^2/24) / dt more than the
  // speed-up (160 mm/s^2 at 8.7 mm/s on a 0.026 mm fillet).
  const double lean = std::min(across * cycle_s / std::max(v, 1e-9), 1.0), theta = v * cycle_s / r;
  const double extra = v * (1 - std::sqrt(1 - lean * lean) + theta * theta / 24) / cycle_s;
  return std::max(along_beside(p.a_cap_mm_s2, across) - extra, 0.0);
}

}  // namespace nck::prep
