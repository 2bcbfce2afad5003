#pragma once
// The runtime state of one spindle interpolator, grouped by concern. Plain
// data that SpindleAxis owns and changes; the configuration it works with
// lives apart in SpindleConfig.
#include <cstdint>

#include "nck/motion/jerk_profile.hpp"
#include "nck/spindle/positioning.hpp"

namespace nck::spindle {

// Tool-related limits (wz[i].vb_min / max_speed_mm_s / a_max); 0 = no limit.
struct ToolDynamics {
  double vb_min_rpm = 0;
  double vb_max_rpm = 0;
  double a_max_deg_s2 = 0;
};

// Where the interpolator's set point is, and how it moved last cycle.
struct SetPoint {
  double pos_deg = 0;         // wrapped into the modulo range
  double vel_deg_s = 0;       // signed set speed
  double accel_deg_s2 = 0;    // last cycle's set acceleration
  double step_deg = 0;        // last cycle's position increment
};

// What the program and the HLI ask of the speed.
struct SpeedCommand {
  double programmed_rpm = 0;  // signed: M3 +, M4 -
  double override_pct = 100;
  bool ignore_override = false;  // G167
  double accel_weight = 1.0;     // G130, as a factor
  bool feedhold = false;
};

// An exact-stop move onto a target: M19, the gear-change position, and the
// last leg of homing onto the reference position.
struct Positioning {
  double target_deg = 0;
  Direction requested_dir = Direction::none;  // as commanded
  int dir = 0;                   // +1 / -1 once planned
  double speed_deg_s = 0;        // positioning speed before override
  bool overridable = true;
  bool planned = false;
  bool done = false;
  double remaining_deg = 0;      // >= 0 along dir
  double brake_accel_deg_s2 = 0; // braking acceleration of the plan
  double speed_cap_deg_s = 0;    // speed the plan's braking covers
  std::uint32_t gear_change_stage = 0;  // gear stage being shifted to
};

// What follows once homing has found the zero mark.
enum class AfterHoming : std::uint8_t { none, go_to_reference, go_to_target, stop };

// Searching the zero mark (G74, or before the first M19 / after the control limit).
struct Homing {
  AfterHoming after = AfterHoming::none;
  bool mark_found = false;       // zero mark passed, now positioning
  int dir = 1;
  // The M19 target kept while homing first.
  double target_deg = 0;
  Direction target_dir = Direction::none;
  double target_speed_deg_s = 0;
  bool target_overridable = true;
};

struct Reference {
  bool homed = false;
  bool lost = false;             // above the control limit: home again
};

// Tool limits in force, and the ones the next start from standstill adopts.
struct ToolLimits {
  ToolDynamics active{};
  ToolDynamics pending{};
  bool has_pending = false;
};

struct Feedforward {
  bool on = false;               // G135 / G137
  double weight = 1.0;           // G136, as a factor
};

// What the path interpolator commanded in axis mode since the last tick.
struct AxisModeInput {
  double step_deg = 0;
  double vel_deg_s = 0;
};

// The jerk-limited ramp in force (slope_type TRAPEZ / SIN2): the plan and
// where the set point is on it. The plan knows magnitudes only: it runs in
// the turning sense `dir` (speeds and accelerations times dir).
struct JerkRamp {
  enum class Kind : std::uint8_t { none, speed, positioning };
  motion::JerkPlan plan{};
  Kind kind = Kind::none;       // what the plan was made for; none: plan anew
  int dir = 1;                  // +1 / -1
  double goal_deg_s = 0;        // speed: the speed aimed at; positioning: the speed cap
  motion::JerkLimits limits{};  // the limits it was made with (a change replans)
  double length_deg = 0;        // positioning: the distance the plan covers
  double t_s = 0;               // time on the plan at the last sample
  double s_deg = 0;             // distance along the plan at the last sample
  // Signed acceleration at the last sample: the exact value a replan starts
  // from (the set point's finite difference is a cycle's mean). 0 whenever
  // anything else moved the set point.
  double a_deg_s2 = 0;
  bool used = false;            // the last tick sampled or checked the plan
};

}  // namespace nck::spindle
