#pragma once
// From per-axis dynamics to limits along the path of one segment: the path
// velocity and accelerations at which no axis exceeds its own limits.
#include <limits>
#include <span>

#include "nck/core/slope.hpp"
#include "nck/motion/jerk_profile.hpp"
#include "nck/motion/segment.hpp"

namespace nck::motion {

// The four ramp times of a slope, s (P-AXIS-00196, 00195, 00198, 00197).
struct RampTimes {
  double acc_up_s = 0.0, acc_down_s = 0.0, dec_up_s = 0.0, dec_down_s = 0.0;
  bool operator==(const RampTimes&) const = default;
};

// One axis (mm/s, mm/s^2; deg/s, deg/s^2 for rotary axes).
struct AxisDynamics {
  double v_max_mm_s = 0.0;
  double a_acc_mm_s2 = 0.0;  // speeding up
  double a_dec_mm_s2 = 0.0;  // slowing down
  // Ramp times of the jerk-limited slopes (s): building up and reducing
  // a_acc and a_dec; tr_geom_s bounds the jerk of curved contours.
  RampTimes tr{};
  double tr_geom_s = 0.0;
};

// Along the path (s in mm of path length).
struct PathLimits {
  double v_max_mm_s = 0.0;
  double a_acc_mm_s2 = 0.0;
  double a_dec_mm_s2 = 0.0;
  // The acceleration profile and, for TRAPEZ/SIN2/HSC, the ramp times in
  // force: the longest of the axes involved (docs/decisions.md, "Jerk-limited
  // slopes, HSC and dynamic weightings"). STEP ignores them.
  SlopeProfile slope = SlopeProfile::step;
  RampTimes tr{};
  bool operator==(const PathLimits&) const = default;
};

// All three finite and > 0.
bool valid(const PathLimits& l) noexcept;

// The jerk-limited profile's view of l (SIN2: sin^2 ramps; HSC: the
// longest ramp time in every phase).
JerkLimits jerk_limits(const PathLimits& l) noexcept;

// Ramp times taken elementwise as the longer of a and b.
RampTimes longest(const RampTimes& a, const RampTimes& b) noexcept;

// Line: min over the moving axes of axis_limit / |direction component|.
// Arc (conservative, holds over the whole arc): the plane axes share the
// smaller of their two limits; the acceleration budget of the plane is split
// between tangential and centripetal parts (each <= a/sqrt(2), so their
// vector sum, and so every plane axis, stays within a), which limits the
// velocity to v_plane <= sqrt(a * r / sqrt(2)); tracking axes as for a line.
// Axes missing from `axes` (index >= axes.size()) are not limited. A segment
// that does not move returns the smallest limits of its axes. setup or rt
// Under a jerk-limited slope an arc's speed and tangential acceleration are
// also held where the contour's own jerk (v^3/r^2 and 3 v a_t / r per axis)
// stays within (1 - 1/sqrt 2) of the plane axes' a/tr (tr the longest of
// the ramp times and tr_geom), so that with the path's jerk (at most
// a/(sqrt 2 tr)) no plane axis exceeds a/tr. The ramp times are the
// longest of the moving axes'.
// v_cap_mm_s (a cubic span only): the span never runs faster, so its
// tangential budget under the jerk-limited slopes is the one at that speed.
PathLimits path_limits(const Segment& seg, std::span<const AxisDynamics> axes,
                       SlopeProfile slope = SlopeProfile::step,
                       double v_cap_mm_s = std::numeric_limits<double>::infinity()) noexcept;

// Limits that hold for a line in any direction through `axes`: each the
// smallest of the axes' (what path_limits gives a segment that does not
// move). For a motion whose start is known only when it runs. setup or rt
PathLimits any_direction_limits(std::span<const AxisDynamics> axes) noexcept;

}  // namespace nck::motion
