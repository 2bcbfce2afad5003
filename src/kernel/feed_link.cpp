#include "nck/kernel/feed_link.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace nck::kernel {
namespace {

bool positive_finite(double x) noexcept { return std::isfinite(x) && x > 0; }

// n before any limit (infinite at the turning centre).
double css_raw_rpm(double v_m_min, double radius_mm) noexcept {
  const double r = std::fabs(radius_mm);
  if (!positive_finite(v_m_min)) return 0;
  if (!(r > 0)) return std::numeric_limits<double>::infinity();
  return 1000.0 * v_m_min / (2.0 * std::numbers::pi * r);
}

double css_cap_rpm(double max_rpm, double vb_max_rpm) noexcept {
  double cap = std::numeric_limits<double>::infinity();
  if (positive_finite(max_rpm)) cap = max_rpm;
  if (positive_finite(vb_max_rpm) && vb_max_rpm < cap) cap = vb_max_rpm;
  return cap;
}

}  // namespace

double link_velocity_mm_s(double rpm, double mm_per_rev) noexcept {
  if (!std::isfinite(rpm) || !positive_finite(mm_per_rev)) return 0;
  return std::fabs(rpm) * mm_per_rev / 60.0;
}

double css_speed_rpm(double v_m_min, double radius_mm, double max_rpm, double vb_max_rpm) noexcept {
  const double n = std::fmin(css_raw_rpm(v_m_min, radius_mm), css_cap_rpm(max_rpm, vb_max_rpm));
  return std::isfinite(n) ? n : 0;
}

bool css_limited(double v_m_min, double radius_mm, double max_rpm, double vb_max_rpm) noexcept {
  return css_raw_rpm(v_m_min, radius_mm) > css_cap_rpm(max_rpm, vb_max_rpm);
}

double tap_angle_deg(double start_deg, double s_mm, double mm_per_rev, double direction) noexcept {
  if (!positive_finite(mm_per_rev)) return start_deg;
  return start_deg + (direction < 0 ? -1.0 : 1.0) * 360.0 * s_mm / mm_per_rev;
}

bool passes_angle(double from_deg, double step_deg, double mark_deg) noexcept {
  if (!std::isfinite(from_deg) || !std::isfinite(step_deg) || !std::isfinite(mark_deg)) return false;
  if (std::fabs(step_deg) >= 360.0) return true;
  // Distance from the start to the mark in the direction of travel, in [0, 360).
  double d = std::fmod(step_deg >= 0 ? mark_deg - from_deg : from_deg - mark_deg, 360.0);
  if (d < 0) d += 360.0;
  return d > 0 ? d <= std::fabs(step_deg) : false;
}

}  // namespace nck::kernel
