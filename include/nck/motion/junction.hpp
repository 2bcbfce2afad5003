#pragma once
// Velocity limits at the transition between two motion blocks, for the
// look-ahead in block preparation (setup side; pure functions).
#include <span>

#include "nck/motion/segment.hpp"

namespace nck::motion {

// The largest path velocity at which going from direction t_in (the unit
// tangent at the end of one block, per axis) into t_out (at the start of
// the next) changes no axis's velocity by more than dv_mm_s[j] in a cycle:
// a kink turns axis j's velocity by v * |t_out[j] - t_in[j]| at once.
// +infinity when no axis's direction changes (collinear or tangent
// transitions); 0 when an axis that turns has no budget. Only the first
// dv_mm_s.size() axes count.
double corner_velocity(const AxisVector& t_in, const AxisVector& t_out, std::span<const double> dv_mm_s) noexcept;

// The velocity at which the path may pass from one block into the next:
// the corner velocity less one braking step of the block before (the
// profile may cross a transition up to one step faster than planned, and
// the kink must fit at that speed too), neither block's cruise velocity
// exceeded; >= 0. The planner's rule for every transition, and the look-
// ahead window's for the transitions a fillet made.
double transition_velocity(const AxisVector& t_in, const AxisVector& t_out, std::span<const double> dv_mm_s,
                           double braking_step_mm_s, double cruise_in_mm_s, double cruise_out_mm_s) noexcept;

// The curvature vector (1/mm, towards the centre; 0 on a line) of seg at
// its start or end: how its tangent turns over a thousandth of its length.
AxisVector end_curvature(const Segment& seg, bool at_end) noexcept;

// Under a jerk-limited slope: the largest path velocity at which passing
// from (t_in, k_in) into (t_out, k_out) (unit tangents and curvature
// vectors, 1/mm, per axis) steps no axis's acceleration by more than
// dv_mm_s[j] / dt_s within a cycle: a kink steps it by v |t_out - t_in| /
// dt, a change of curvature (a tangent arc into a line) by v^2 |k_out -
// k_in|. +infinity where neither changes.
double curvature_step_velocity(const AxisVector& t_in, const AxisVector& k_in, const AxisVector& t_out,
                               const AxisVector& k_out, std::span<const double> dv_mm_s, double dt_s) noexcept;

// The highest velocity at the start of a path of length_mm from which
// PathProfile, braking with a_dec_mm_s2 in cycles of dt_s, still reaches
// v_exit_mm_s at its end (the same discrete braking law, so the profile
// never finds itself too fast).
double entry_velocity_limit(double length_mm, double v_exit_mm_s, double a_dec_mm_s2, double dt_s) noexcept;

}  // namespace nck::motion
