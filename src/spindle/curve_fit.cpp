// Coefficient fitting for the characteristic acceleration curves (FCT-S1
// 2.8.4.1). P1 = (n_grenz, a_konst) is fixed by the parameters; the user
// gives the remaining points on the drive's a(n) curve.
#include <cmath>
#include <fmt/format.h>

#include <vector>
#include "nck/spindle/accel_curve.hpp"

namespace nck::spindle {
namespace {

using Points = std::vector<CurvePoint>;

// Checks the inputs and returns the points above n_grenz, in the given order.
std::expected<Points, std::string> points_above(double n_grenz, double a_konst,
                                                std::span<const CurvePoint> points,
                                                std::size_t needed, const char* kind) {
  if (!(std::isfinite(n_grenz) && n_grenz > 0))
    return std::unexpected(fmt::format("n_grenz must be a positive speed, got {}", n_grenz));
  if (!(std::isfinite(a_konst) && a_konst > 0))
    return std::unexpected(fmt::format("a_konst must be a positive acceleration, got {}", a_konst));
  Points out;
  for (const CurvePoint& p : points) {
    if (!std::isfinite(p.speed_deg_s) || !std::isfinite(p.accel_deg_s2) || p.accel_deg_s2 <= 0)
      return std::unexpected(fmt::format("point ({}, {}) is not a positive finite acceleration",
                                         p.speed_deg_s, p.accel_deg_s2));
    if (p.speed_deg_s == n_grenz) continue;  // P1, already given by the parameters
    if (p.speed_deg_s < n_grenz)
      return std::unexpected(fmt::format("point speed {} lies below n_grenz {}", p.speed_deg_s, n_grenz));
    for (const CurvePoint& q : out)
      if (q.speed_deg_s == p.speed_deg_s)
        return std::unexpected(fmt::format("two points share the speed {}", p.speed_deg_s));
    out.push_back(p);
  }
  if (out.size() != needed)
    return std::unexpected(fmt::format("the {} needs exactly {} points above n_grenz (besides "
                                       "n_grenz/a_konst), got {}",
                                       kind, needed, out.size()));
  return out;
}

bool usable(double v) { return std::isfinite(v); }

}  // namespace

std::expected<Coefficients, std::string> fit_polynomial(double limit_speed_deg_s, double const_accel_deg_s2,
                                                        std::span<const CurvePoint> points) {
  auto pts = points_above(limit_speed_deg_s, const_accel_deg_s2, points, 3, "polynomial");
  if (!pts) return std::unexpected(pts.error());
  // The seed's closed form with dn_i = n_i - n_grenz and e_i = a_konst - a(n_i).
  const double d2 = (*pts)[0].speed_deg_s - limit_speed_deg_s;
  const double d3 = (*pts)[1].speed_deg_s - limit_speed_deg_s;
  const double d4 = (*pts)[2].speed_deg_s - limit_speed_deg_s;
  const double e2 = const_accel_deg_s2 - (*pts)[0].accel_deg_s2;
  const double e3 = const_accel_deg_s2 - (*pts)[1].accel_deg_s2;
  const double e4 = const_accel_deg_s2 - (*pts)[2].accel_deg_s2;
  Coefficients c;
  c.b3 = (d4 * e2 - d2 * e4) / (d4 * d2 * (d4 - d2) * (d4 - d3)) -
         (d3 * e2 - d2 * e3) / (d3 * d2 * (d3 - d2) * (d4 - d3));
  c.b2 = ((d3 / d2) * e2 - c.b3 * d3 * (d3 * d3 - d2 * d2) - e3) / (d3 * (d3 - d2));
  c.b1 = -e2 / d2 - c.b3 * d2 * d2 - c.b2 * d2;
  if (!usable(c.b1) || !usable(c.b2) || !usable(c.b3))
    return std::unexpected(std::string("the polynomial system is singular for these points"));
  return c;
}

std::expected<Coefficients, std::string> fit_hyperbola(double limit_speed_deg_s, double const_accel_deg_s2,
                                                       std::span<const CurvePoint> points) {
  auto pts = points_above(limit_speed_deg_s, const_accel_deg_s2, points, 2, "hyperbola");
  if (!pts) return std::unexpected(pts.error());
  // With u = b2 and w = b2*b3 each point gives one linear equation
  // (c-1) + u(c-x) + w(c-x^2) = 0, c = a_konst/a(n), x = (n/n_grenz)^2.
  double m[2][3];
  for (int i = 0; i < 2; ++i) {
    const double r = (*pts)[i].speed_deg_s / limit_speed_deg_s;
    const double x = r * r;
    const double c = const_accel_deg_s2 / (*pts)[i].accel_deg_s2;
    m[i][0] = c - x;
    m[i][1] = c - x * x;
    m[i][2] = 1.0 - c;  // right-hand side
  }
  const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
  const double scale = std::fabs(m[0][0] * m[1][1]) + std::fabs(m[0][1] * m[1][0]);
  if (!(std::fabs(det) > 1e-12 * scale) || scale == 0)
    return std::unexpected(std::string("the hyperbola system is singular for these points"));
  const double u = (m[0][2] * m[1][1] - m[0][1] * m[1][2]) / det;
  const double w = (m[0][0] * m[1][2] - m[0][2] * m[1][0]) / det;
  if (u == 0)
    return std::unexpected(std::string("the fitted b2 is 0, so b3 = w/b2 is undefined"));
  Coefficients c;
  c.b2 = u;
  c.b3 = w / u;
  c.b1 = const_accel_deg_s2 * (1.0 + u + w);
  if (!usable(c.b1) || !usable(c.b2) || !usable(c.b3))
    return std::unexpected(std::string("the hyperbola fit did not give finite coefficients"));
  return c;
}

}  // namespace nck::spindle
