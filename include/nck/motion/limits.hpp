#pragma once
// From per-axis dynamics to limits along the path of one segment: the path
// velocity and accelerations at which no axis exceeds its own limits.
#include <span>

#include "nck/motion/segment.hpp"

namespace nck::motion {

// One axis (mm/s, mm/s^2; deg/s, deg/s^2 for rotary axes).
struct AxisDynamics {
  double v_max_mm_s = 0.0;
  double a_acc_mm_s2 = 0.0;  // speeding up
  double a_dec_mm_s2 = 0.0;  // slowing down
};

// Along the path (s in mm of path length).
struct PathLimits {
  double v_max_mm_s = 0.0;
  double a_acc_mm_s2 = 0.0;
  double a_dec_mm_s2 = 0.0;
};

// All three finite and > 0.
bool valid(const PathLimits& l) noexcept;

// Line: min over the moving axes of axis_limit / |direction component|.
// Arc (conservative, holds over the whole arc): the plane axes share the
// smaller of their two limits; the acceleration budget of the plane is split
// between tangential and centripetal parts (each <= a/sqrt(2), so their
// vector sum, and so every plane axis, stays within a), which limits the
// velocity to v_plane <= sqrt(a * r / sqrt(2)); tracking axes as for a line.
// Axes missing from `axes` (index >= axes.size()) are not limited. A segment
// that does not move returns the smallest limits of its axes. setup or rt
PathLimits path_limits(const Segment& seg, std::span<const AxisDynamics> axes) noexcept;

}  // namespace nck::motion
