#pragma once
// Online trapezoidal velocity profile along a path of known length, stepped
// once per cycle. It speeds up with a_acc, cruises at min(v_cmd * override,
// v_max) and brakes with a_dec so that it stops exactly at the end.
//
// Under a jerk-limited slope (limits.slope TRAPEZ, SIN2, HSC) the segment
// follows a JerkPlan instead: continuous-time phases sampled at the cycle
// times, replanned from the exact state when the target speed or the end
// speed changes, and the time run past a segment's end carried into the
// next one (path_profile_jerk.cpp).
//
// STEP's discrete-time model: each step sets the velocity v_k for the whole cycle and
// moves s by v_k * dt, so the finite differences of the set points ARE the
// profile's velocity and acceleration. The braking speed is computed from the
// remaining distance with the discrete sum (not v = sqrt(2ad)), so the last
// cycles do not crawl: the final cycle covers exactly what is left.
#include <cstddef>
#include <limits>

#include "nck/motion/jerk_profile.hpp"
#include "nck/motion/limits.hpp"

namespace nck::motion {

// HSC (#SLOPE [TYPE=HSC], P-CHAN-00071 = 3): the segment that starts and
// the ones after it that the path runs through at speed, planned as one
// jerk-limited profile (acceleration carried across their transitions).
// length_mm from the segment's start to the chain's end; limits the
// smallest accelerations and longest ramp times of its segments; the
// chain ends at v_end_mm_s with acceleration 0. length_mm 0: no chain.
struct PathChain {
  double length_mm = 0.0;
  PathLimits limits{};
  double v_end_mm_s = 0.0;
  bool operator==(const PathChain&) const = default;
};

struct ProfileSample {
  double s_mm = 0.0;         // path length travelled within the segment
  double v_mm_s = 0.0;       // velocity during the last step
  double a_mm_s2 = 0.0;      // (v_k - v_{k-1}) / dt of the last step
  bool finished = false;     // s_mm == length (end reached)
  bool braking = false;      // the braking curve towards the end speed set the velocity
};

class PathProfile {
 public:
  // Prepares a segment. The motion continues from the current velocity (0
  // after a stop or reset()); if the previous segment ended with v_end > 0,
  // the distance it ran past its end is carried into this one.
  // v_end > 0 ends the segment at that speed without stopping (for
  // continuous-path blending; the caller must keep v_end reachable by the
  // next segment). Returns false (and becomes finished, s = 0) when
  // length > 0 and v_cmd or a limit is not finite and positive. rt
  bool start(double length_mm, double v_cmd_mm_s, const PathLimits& limits,
             double v_end_mm_s = 0.0, const PathChain& chain = {}) noexcept;
  // HSC: the chain changed while the segment runs (preparation queued more,
  // the braking reserve at its end moved). A chain that only grew is taken
  // when the plan in force nears its braking (before that it brakes earlier
  // than the longer chain needs: still safe). rt
  void set_chain(const PathChain& chain) noexcept;

  // One cycle of dt seconds. override_factor 1 = 100 %; 0 = feedhold (brakes
  // to standstill with a_dec and stays until the override rises again);
  // negative or NaN is taken as 0. dt <= 0 or NaN changes nothing. rt
  ProfileSample step(double dt_s, double override_factor) noexcept;

  // Back to standstill with no carried distance (e.g. after an abort). rt
  void reset() noexcept;
  // E-stop: from now on (this segment and the ones after it, until reset())
  // the profile brakes with at least a_mm_s2 (its own deceleration when that
  // is higher, so that it still stops at an exact-stop end), as a STEP
  // profile: the quick stop of a drive ramps its speed, it does not limit
  // its jerk. Give it with override 0 (the target speed). rt
  void brake_for_emergency(double a_mm_s2) noexcept;
  bool emergency() const noexcept { return emergency_a_mm_s2_ > 0.0; }

  // A per-cycle limit on the commanded velocity (a spindle coupling: G95,
  // G33, G63, G331), set before step(). The profile ramps to
  // min(min(v_cmd, limit) x override, v_max) with its accelerations; a limit of
  // 0 holds the path (braking). Negative or NaN clears the limit (no
  // coupling). start() clears it. rt
  void set_velocity_limit(double v_mm_s) noexcept;
  // The first step after start() changes the speed by at most a * dt (a
  // start out of a sharp corner's exact stop; 0 stands still a cycle). rt
  void limit_first_step(double a_mm_s2) noexcept;
  // Passing in from a fillet (STEP): the first step changes the speed by at
  // most a * dt (and the segment's own limits), instead of the fillet's
  // tangential acceleration. rt
  void pass_first_step(double a_mm_s2) noexcept;
  // The next segment is a fillet (STEP): the speed to pass at is reached in
  // the cycle that crosses into it, not a cycle before (kHoldCycles 1
  // instead of 2). Set after start(). rt
  void pass_into_fillet() noexcept;
  // STEP: the path brakes across the segment's end: besides passing it at
  // no more than v_end (then a ceiling, the corner's), it follows the
  // braking staircase to standstill beyond_mm past the end, which the
  // segments after it continue; the crossing cycle may brake, never speed
  // up. The look-ahead window guarantees the segments after it can follow.
  // 0: none. Set after start(). rt
  void brake_through(double beyond_mm) noexcept;
  // Changes the speed at the segment's end while it runs (the kernel's
  // braking reserve: 0 while no successor is queued, the planned v_end once
  // one is). Raising it is always possible; lowering it is only safe while
  // the braking curve to the new value is not yet passed. rt
  void set_end_velocity(double v_end_mm_s) noexcept;
  double end_velocity() const noexcept { return v_end_mm_s_; }
  // Ignore the feed override (G33: the path follows the spindle). rt
  void set_override_ignored(bool ignored) noexcept { override_ignored_ = ignored; }
  bool override_ignored() const noexcept { return override_ignored_; }
  // The coupling's limit set for this cycle (< 0: none).
  double velocity_limit() const noexcept { return v_limit_mm_s_; }

  // Whether the path can still stop at the segment's end from where it is
  // (an operator hold at the block end). rt
  bool stop_fits(double dt_s) const noexcept;
  // The path acceleration of the last step (jerk-limited: the profile's). rt
  double a() const noexcept { return a_mm_s2_; }
  bool jerk_limited_now() const noexcept { return jerk_; }

  double s() const noexcept { return s_mm_; }
  double v() const noexcept { return v_mm_s_; }
  double length() const noexcept { return length_mm_; }
  double remaining() const noexcept { return length_mm_ - s_mm_; }
  bool finished() const noexcept { return finished_; }
  const PathLimits& limits() const noexcept { return limits_; }

 private:
  double target_velocity(double override_factor) const noexcept;
  // The jerk-limited twins of start() and step() (path_profile_jerk.cpp).
  void start_jerk(double carry_mm, bool passing) noexcept;
  // may_keep: only the target changed (an override step, a feedhold, a reset).
  void replan_jerk(double target_mm_s, bool may_keep = false) noexcept;
  ProfileSample step_jerk(double dt_s, double override_factor) noexcept;
  ProfileSample finish_jerk(double t_end_s, double t1_s) noexcept;
  // HSC: this segment's end lies inside a chain (start() and set_chain()
  // keep only chains longer than the segment).
  bool chained() const noexcept { return chain_.length_mm > 0.0; }
  ProfileSample finish(double v_step_mm_s, double v_prev_mm_s, double dt_s, double past_end_mm) noexcept;

  double length_mm_ = 0.0;
  double v_cmd_mm_s_ = 0.0;  // min(v_cmd, v_max)
  double v_end_mm_s_ = 0.0;
  PathLimits limits_{};
  double s_mm_ = 0.0;
  double v_mm_s_ = 0.0;
  double carry_mm_ = 0.0;  // distance run past the previous segment's end
  // The first step's accelerations (infinite: the segment's own).
  double first_acc_mm_s2_ = std::numeric_limits<double>::infinity();
  double first_dec_mm_s2_ = std::numeric_limits<double>::infinity();
  bool finished_ = true;
  double v_limit_mm_s_ = -1.0;  // < 0: none
  double beyond_mm_ = 0.0, beyond_dt_s_ = 0.0;  // pass_brake_distance for that cycle time
  bool override_ignored_ = false;
  bool into_fillet_ = false;  // pass_into_fillet()
  double through_mm_ = 0.0;   // brake_through(), 0: none
  // Jerk-limited slopes: the plan (relative to s = plan_s0_mm_ at its start),
  // the time in it, the acceleration now, and what it was planned for.
  bool jerk_ = false;
  JerkPlan plan_{};
  BlockPlanKind plan_kind_ = BlockPlanKind::fits;
  double plan_s0_mm_ = 0.0, t_s_ = 0.0, a_mm_s2_ = 0.0;
  double plan_target_mm_s_ = -1.0, plan_end_mm_s_ = -1.0;
  double carry_s_ = 0.0;  // time run past the previous segment's end
  double last_override_ = 1.0;
  PathChain chain_{};           // HSC: the chain planned over (length 0: none)
  bool chain_changed_ = false;  // set_chain brought a new chain not planned yet
  double emergency_a_mm_s2_ = 0.0;  // brake_for_emergency(), 0: none
};

// Largest velocity v for this cycle such that moving v*dt now and then
// braking by a*dt per cycle ends at standstill within remaining_mm. Stepping
// with it and then a*dt less each cycle ends exactly at the target. rt
double discrete_brake_velocity(double remaining_mm, double a_mm_s2, double dt_s) noexcept;

// Distance covered when braking from v to standstill in that discrete way
// (the inverse of discrete_brake_velocity). rt
double discrete_brake_distance(double v_mm_s, double a_mm_s2, double dt_s) noexcept;

// How far beyond its end the braking staircase of a segment that ends at
// v_end > 0 would come to rest (negative: before it). The profile reaches
// v_end two cycles before the end and holds it there, so the cycle that
// passes into the next segment, lying on both, does not change the speed as
// well (docs/decisions.md, "Continuous path and corner blending"). 0 for
// v_end = 0. rt
double pass_brake_distance(double v_end_mm_s, double a_mm_s2, double dt_s) noexcept;
// The same for a segment that holds v_end over hold_cycles cycles' travel. rt
double pass_brake_distance(double v_end_mm_s, double a_mm_s2, double dt_s, double hold_cycles) noexcept;

// Analytic (continuous-time) duration of a rest-to-rest trapezoid or
// triangle: for tests and estimates. 0 for length 0; +infinity when the
// motion cannot happen (v or a limit not positive).
double duration_estimate(double length_mm, double v_cmd_mm_s, const PathLimits& limits) noexcept;

}  // namespace nck::motion
