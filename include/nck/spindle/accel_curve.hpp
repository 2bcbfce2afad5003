#pragma once
// Speed-dependent spindle acceleration (FCT-S1 2.8.4): the characteristic
// curves a(n) of beschl_kennlinie and the fitting of their coefficients from
// points of the drive's torque curve. Pure functions; speeds in deg/s,
// accelerations in deg/s^2 (as in the seed's tables).
#include <expected>
#include <span>
#include <string>

#include "nck/config/machine.hpp"

namespace nck::spindle {

// Acceleration the curve allows at |speed_deg_s|. Type 0 (no curve) returns
// `slope_accel_deg_s2`, the caller's accel_mm_s2 / decel_mm_s2. Types 1..3 use
// a_konst below n_grenz and never return less than a_min. An unknown type or
// a non-finite result falls back to the slope value. // rt
double curve_accel_deg_s2(const config::AccelCurve& curve, double speed_deg_s,
                          double slope_accel_deg_s2 = 0) noexcept;

struct CurvePoint {
  double speed_deg_s = 0;
  double accel_deg_s2 = 0;
};

struct Coefficients {
  double b1 = 0, b2 = 0, b3 = 0;
};

// Polynomial a(n) = b3*dn^3 + b2*dn^2 + b1*dn + a_konst, dn = n - n_grenz.
// Needs exactly 3 points above n_grenz (the seed's P2..P4); a point at
// n_grenz itself (P1) is skipped. // setup
std::expected<Coefficients, std::string> fit_polynomial(double limit_speed_deg_s, double const_accel_deg_s2,
                                                        std::span<const CurvePoint> points);

// Hyperbola a(n) = b1 / (1 + b2*x*(1 + b3*x)), x = (n/n_grenz)^2, through
// (n_grenz, a_konst). Needs exactly 2 points above n_grenz (P2, P3); a point
// at n_grenz is skipped. // setup
std::expected<Coefficients, std::string> fit_hyperbola(double limit_speed_deg_s, double const_accel_deg_s2,
                                                       std::span<const CurvePoint> points);

}  // namespace nck::spindle
