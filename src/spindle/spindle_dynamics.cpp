// The limits the spindle interpolator works with: acceleration from the slope
// or characteristic curve of the active gear stage, weighted by G130 and
// capped by a_max and the tool; speed capped by max_speed_mm_s and the tool.
#include <algorithm>
#include <cmath>

#include "nck/spindle/accel_curve.hpp"
#include "nck/spindle/spindle_axis.hpp"

namespace nck::spindle {

double SpindleAxis::accel_limit(double a_deg_s2) const noexcept {
  double a = a_deg_s2 * speed_.accel_weight;
  if (gear().accel_max_deg_s2 > 0) a = std::min(a, gear().accel_max_deg_s2);
  if (tool_.active.a_max_deg_s2 > 0) a = std::min(a, tool_.active.a_max_deg_s2);
  // A zero or broken parameter must not freeze the spindle for ever.
  return std::isfinite(a) && a > 0 ? a : 1.0;
}

double SpindleAxis::accel_up(double speed_deg_s) const noexcept {
  return accel_limit(curve_accel_deg_s2(gear().accel_curve, speed_deg_s, gear().accel_deg_s2));
}

double SpindleAxis::accel_down(double speed_deg_s) const noexcept {
  return accel_limit(curve_accel_deg_s2(gear().accel_curve, speed_deg_s, gear().decel_deg_s2));
}

double SpindleAxis::min_accel_down(double up_to_deg_s) const noexcept {
  // Positioning brakes along sqrt(2 a s) with one a: take the lowest the
  // curve allows on the way down (curves need not be monotonic).
  constexpr int kSamples = 64;
  double a = accel_down(0);
  const double top = std::fabs(up_to_deg_s);
  for (int i = 1; i <= kSamples; ++i) a = std::min(a, accel_down(top * i / kSamples));
  return a;
}

double SpindleAxis::max_speed_deg_s() const noexcept {
  double v = gear().speed_max_deg_s > 0 ? gear().speed_max_deg_s : 1e12;
  if (tool_.active.vb_max_rpm > 0) v = std::min(v, rpm_to_deg_s(tool_.active.vb_max_rpm));
  return v;
}

double SpindleAxis::override_factor() const noexcept {
  return speed_.ignore_override ? 1.0 : speed_.override_pct / 100.0;
}

double SpindleAxis::limit_speed(double speed_deg_s) const noexcept {
  // |speed| capped by max_speed_mm_s and the tool's max_speed_mm_s; 0 stays 0.
  const double s = std::fabs(speed_deg_s);
  if (s == 0 || !std::isfinite(s)) return 0;
  return std::copysign(std::min(s, max_speed_deg_s()), speed_deg_s);
}

double SpindleAxis::limit_rotation_speed(double speed_deg_s) const noexcept {
  // The tool's minimum speed holds only for endless turning (FCT-S1 2.8.5),
  // never for M19 or homing; 0 stays 0 (no rotation asked for).
  const double s = std::fabs(speed_deg_s);
  if (s == 0 || !std::isfinite(s)) return 0;
  const double lowest = tool_.active.vb_min_rpm > 0 ? rpm_to_deg_s(tool_.active.vb_min_rpm) : 0.0;
  return limit_speed(std::copysign(std::max(s, lowest), speed_deg_s));
}

double SpindleAxis::rotation_speed_deg_s() const noexcept {
  const RotationInputs in{speed_.programmed_rpm, speed_.override_pct, tool_.active.vb_min_rpm,
                          tool_.active.vb_max_rpm, speed_.ignore_override, gear_};
  if (!(rotation_seen_ && *rotation_seen_ == in)) {
    rotation_deg_s_ = compute_rotation_speed_deg_s();
    rotation_seen_ = in;
  }
  return rotation_deg_s_;
}

double SpindleAxis::compute_rotation_speed_deg_s() const noexcept {
  return limit_rotation_speed(rpm_to_deg_s(speed_.programmed_rpm) * override_factor());
}

}  // namespace nck::spindle
