#include "nck/spindle/accel_curve.hpp"

#include <algorithm>
#include <cmath>

namespace nck::spindle {
namespace {

double hyperbola(const config::AccelCurve& c, double n) {
  const double x = (n / c.limit_speed_deg_s) * (n / c.limit_speed_deg_s);
  return c.b1 / (1.0 + c.b2 * x * (1.0 + c.b3 * x));
}

double polynomial(const config::AccelCurve& c, double n) {
  // FCT-S1 §2.8.4.1 prints dn = n_grenz - n, but its own example coefficients
  // reproduce its table only with dn = n - n_grenz, which nck uses.
  const double dn = n - c.limit_speed_deg_s;
  return ((c.b3 * dn + c.b2) * dn + c.b1) * dn + c.const_accel_deg_s2;
}

double asynchronous(const config::AccelCurve& c, double n) {
  // Constant torque up to N1, constant power (1/n) up to N2, then 1/n^2.
  if (n <= c.n1_deg_s || n <= 0) return c.a_max_deg_s2;
  if (n <= c.n2_deg_s) return c.a_max_deg_s2 * c.n1_deg_s / n;
  return c.a_max_deg_s2 * c.n1_deg_s * c.n2_deg_s / (n * n);
}

}  // namespace

double curve_accel_deg_s2(const config::AccelCurve& curve, double speed_deg_s,
                          double slope_accel_deg_s2) noexcept {
  const double n = std::fabs(speed_deg_s);
  if (curve.type < 1 || curve.type > 3 || !std::isfinite(n)) return slope_accel_deg_s2;
  if (curve.type != 3 && curve.limit_speed_deg_s <= 0) return slope_accel_deg_s2;  // curve unusable
  double a = 0;
  if (curve.limit_speed_deg_s > 0 && n < curve.limit_speed_deg_s) {
    a = curve.const_accel_deg_s2;
  } else if (curve.type == 1) {
    a = hyperbola(curve, n);
  } else if (curve.type == 2) {
    a = polynomial(curve, n);
  } else {
    a = asynchronous(curve, n);
  }
  if (!std::isfinite(a)) return slope_accel_deg_s2;
  return std::max(a, curve.a_min_deg_s2);
}

}  // namespace nck::spindle
