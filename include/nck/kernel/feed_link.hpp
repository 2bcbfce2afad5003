#pragma once
// Spindle-path couplings as a per-cycle law (FCT-S1 2.8.6, 2.8.7, 2.8.9;
// TF5200 G95, G96). Preparation describes the coupling in fixed-size data; the
// channel evaluates it every cycle and hands the result to the path as a
// commanded-velocity limit (PathProfile::set_commanded_velocity), or to the
// spindle as a speed (G96) or a position (tapping). Nothing here knows the
// path planner: a continuous-path look-ahead can honour the same limit.
#include <cstdint>

namespace nck::kernel {

enum class FeedLinkKind : std::uint8_t {
  none,       // G94 / G93: the path speed is the planned one
  per_rev,    // G95: v = spindle speed x F (mm/rev)
  thread,     // G33: v = actual spindle speed x pitch; starts on zero mark + OFFSET
  tap,        // G63: the spindle follows the path (pitch = F / S)
  tap_rigid,  // G331 / G332: the spindle follows the path (pitch K)
};

// How the path is coupled to a spindle in one block.
struct FeedLink {
  FeedLinkKind kind = FeedLinkKind::none;
  std::int8_t spindle = -1;  // kernel spindle index
  double mm_per_rev = 0;     // G95 F; G33 / G63 / G331 pitch along the path (> 0)
  // G63 / G331 / G332: spindle turn direction (+1 M3 sense, -1 M4 sense)
  // while the path moves forward; G95 with a PLC spindle: the programmed rpm.
  double direction = 1;
  double programmed_rpm = 0;  // G95 on a PLC spindle (programmed values only, TF5200 G95)
  // Tapping: the spindle's top speed as an axis (G63: the gear stage of
  // P-AXIS-00052 def_cax_gear_st), 0 = its current gear stage's.
  double spindle_max_rpm = 0;
  bool use_programmed = false;
  double start_deg = 0;       // G33: spindle angle at which the path starts
  bool ignore_override = true;  // G33: the path follows the spindle, not the feed override
  // G33 continuing a thread chain (P-CHAN-00837): the path passes on from the
  // G33 block before without waiting for the start angle again.
  bool chained = false;
};

// Constant cutting speed (G96): the spindle speed follows the face axis.
struct CssLink {
  bool active = false;
  std::int8_t spindle = -1;    // kernel spindle index
  std::int8_t face_axis = -1;  // channel axis index of the face-turning axis
  double v_m_min = 0;          // cutting speed
  double max_rpm = 0;          // G196 limit, 0 = none
  double centre_mm = 0;        // machine position of the turning centre on the face axis
};

// Path velocity a feed link allows for a spindle turning at `rpm`
// (|rpm| x mm/rev / 60; 0 for none or invalid data). rt
double link_velocity_mm_s(double rpm, double mm_per_rev) noexcept;

// G96: n = 1000 v / (2 pi r), limited by max_rpm (G196, ignored when <= 0)
// and by vb_max_rpm (the gear stage, ignored when <= 0). At r = 0 the
// limit applies; without any limit the result is 0. rt
double css_speed_rpm(double v_m_min, double radius_mm, double max_rpm, double vb_max_rpm) noexcept;

// Whether css_speed_rpm was cut by a limit at this radius. rt
bool css_limited(double v_m_min, double radius_mm, double max_rpm, double vb_max_rpm) noexcept;

// Tapping: the spindle angle after the path travelled s_mm from where the
// spindle stood at start_deg (unwrapped, degrees). rt
double tap_angle_deg(double start_deg, double s_mm, double mm_per_rev, double direction) noexcept;

// G33: did the spindle, moving from `from_deg` by `step_deg` this cycle,
// pass `mark_deg` (all modulo 360)? A step of a full turn or more passes it. rt
bool passes_angle(double from_deg, double step_deg, double mark_deg) noexcept;

}  // namespace nck::kernel
