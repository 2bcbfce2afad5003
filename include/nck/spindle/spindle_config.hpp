#pragma once
// What one spindle interpolator needs to know about its machine, built once
// at setup from the machine model and immutable afterwards (grblHAL keeps a
// spindle's capabilities apart from its runtime state; so do we). The list
// keys stay German in the config layer; here every field says what it means,
// with its unit. The cyclic object holds no pointers into the machine model.
#include <array>
#include <cstdint>

#include "nck/config/machine.hpp"
#include "nck/core/slope.hpp"
#include "nck/motion/limits.hpp"
#include "nck/spindle/drive_scaling.hpp"
#include "nck/spindle/positioning.hpp"

namespace nck::spindle {

// The data of one gear stage the interpolator uses (config::GearStage,
// getriebe[i]). Speeds in deg/s, accelerations in deg/s^2.
struct GearConfig {
  double accel_deg_s2 = 1000;          // a_beschl: speeding up
  double decel_deg_s2 = 1000;          // a_brems: slowing down
  double accel_max_deg_s2 = 1000;      // a_max: cap over every weighting; <= 0 none
  double speed_max_deg_s = 200;        // vb_max; <= 0 none
  double rapid_speed_deg_s = 166.666;  // vb_eilgang: gear-change approach, homing
  double modulo_low_deg = 0;           // modulou
  double modulo_high_deg = 360;        // moduloo
  double zero_speed_deg_s = 0.1;       // vb_min_null: standstill below this
  double control_limit_deg_s = 200;    // vb_regelgrenze: encoder invalid above; <= 0 none
  double gear_change_pos_deg = 0;      // getr_schalt_pos
  double reference_pos_deg = 0;        // pos_refpkt: the zero mark
  bool reverse_sense = false;          // reverse: drive output and actual values with flipped sign
  config::AccelCurve accel_curve{};    // beschl_kennlinie: a(n) instead of the slope
  // slope_type: STEP (acceleration steps) or the jerk-limited TRAPEZ / SIN2
  // ramps with the feed ramp times of a_beschl / a_brems (P-AXIS-00195...198).
  SlopeProfile slope = SlopeProfile::step;
  motion::RampTimes ramp_times{};

  static GearConfig from(const config::GearStage& g) noexcept;  // setup

  // Width of the modulo range; 360 when the parameters give none. // rt
  double range_deg() const noexcept;
  // pos_deg wrapped into [modulo_low_deg, modulo_high_deg). // rt
  double wrap(double pos_deg) const noexcept { return wrap_modulo(pos_deg, modulo_low_deg, modulo_high_deg); }
};

struct SpindleConfig {
  std::array<GearConfig, config::kMaxGearStages> gears{};  // index 0 = stage 1
  std::uint32_t initial_gear = 1;
  Direction preferred_direction = Direction::none;  // vorz_richtung with beweg_richt
  double speed_reached_tolerance_permille = 100;    // vb_prozent: +-10 %
  bool keep_running_on_reset = false;   // no_stop_by_channel_reset
  bool open_loop = false;       // speed-controlled (antr.operation_mode OPEN_POSITION_LOOP*)
  bool can_position = true;     // position feedback present (else 70252 on M19 / G74)
  bool auto_homing = true;      // home before M19 / M5 when unreferenced (not with achs_mode 0x100)
  bool drive_homing = false;    // digital drive (CiA 402): G74 lets the drive home; never automatic
  bool sensorless = false;      // open loop without any feedback: acknowledge from the set speed
  bool plc_control = false;     // PLC spindle over the channel HLI (no axis list)
  SpeedScaling drive_speed_scaling{};   // antr.v_reso_num / v_reso_denom / v_time_base
  double cycle_s = 0.001;
  double in_position_window_deg = 0.01;  // nck's own: no parameter in the seeds

  // `axis` may be null (PLC spindle without an axis list): default gear data. // setup
  static SpindleConfig from(const config::AxisConfig* axis, const config::ChannelSpindle& sp,
                            double cycle_s);
};

}  // namespace nck::spindle
