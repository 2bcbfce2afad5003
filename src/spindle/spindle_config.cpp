// The config -> spindle conversion: the only place that reads the German
// list names of an axis for the spindle interpolator.
#include "nck/spindle/spindle_config.hpp"

#include <algorithm>
#include <cmath>

#include "nck/config/drive_feedback.hpp"

namespace nck::spindle {

GearConfig GearConfig::from(const config::GearStage& g) noexcept {
  GearConfig c;
  c.accel_deg_s2 = g.accel_mm_s2;
  c.decel_deg_s2 = g.decel_mm_s2;
  c.accel_max_deg_s2 = g.a_max;
  c.speed_max_deg_s = g.max_speed_mm_s;
  c.rapid_speed_deg_s = g.rapid_mm_s;
  c.modulo_low_deg = g.modulo_lower;
  c.modulo_high_deg = g.modulo_upper;
  c.zero_speed_deg_s = g.zero_speed_deg_s;
  c.control_limit_deg_s = g.control_limit_deg_s;
  c.gear_change_pos_deg = g.gear_change_pos_deg;
  c.reference_pos_deg = g.reference_pos;
  c.accel_curve = g.curve;
  // The config layer made it STEP where a curve gives the acceleration.
  c.slope = g.slope_type;
  c.ramp_times = motion::RampTimes{g.tr_acc_up_s, g.tr_acc_down_s, g.tr_dec_up_s, g.tr_dec_down_s};
  c.reverse_sense = g.reverse_sense;
  return c;
}

double GearConfig::range_deg() const noexcept {
  const double r = modulo_high_deg - modulo_low_deg;
  return r > 0 && std::isfinite(r) ? r : 360.0;
}

namespace {

// P-AXIS-00015 bit ACHSMODE_KEINE_AUTO_RPF: no automatic homing before M19
// (drive-controlled homing with G74 only, FCT-S1 2.7).
constexpr std::uint32_t kNoAutomaticHoming = 0x100;

// A PLC spindle over the channel HLI has no axis list: its drive belongs to
// the PLC, so the NC must not cap its speed with the machine model's default
// max_speed_mm_s (200 deg/s = 33.3 rpm) nor open a control limit it does not have.
SpindleConfig without_axis_limits(SpindleConfig c) noexcept {
  for (GearConfig& g : c.gears) {
    g.speed_max_deg_s = 0;
    g.control_limit_deg_s = 0;
  }
  return c;
}

}  // namespace

SpindleConfig SpindleConfig::from(const config::AxisConfig* axis, const config::ChannelSpindle& sp,
                                  double cycle_s) {
  SpindleConfig c;
  c.plc_control = sp.plc_control;
  c.cycle_s = cycle_s;
  // Without an axis list the gear stages keep the machine model's defaults.
  const auto stages = axis != nullptr ? axis->gears : decltype(axis->gears){};
  std::ranges::transform(stages, c.gears.begin(), GearConfig::from);
  if (axis == nullptr) return without_axis_limits(c);
  c.initial_gear = std::clamp<std::uint32_t>(axis->initial_gear_stage, 1, config::kMaxGearStages);
  c.preferred_direction = spindle::preferred_direction(*axis);
  c.speed_reached_tolerance_permille = axis->speed_reached_tolerance_permille;
  c.keep_running_on_reset = axis->no_stop_by_channel_reset;
  c.open_loop = axis->is_speed_controlled();
  c.can_position = config::knows_position(*axis);
  // Neither position nor speed feedback: the speed acknowledgement comes
  // from the interpolator's own command value (FCT-S1 2.2.4, case 3).
  c.sensorless = c.open_loop && !c.can_position && axis->drive_mode != config::DriveMode::open_loop_vel_feedback;
  // With a digital drive the drive homes on G74, and automatic homing is
  // not possible (FCT-S1 2.7): it is off whatever achs_mode says.
  c.drive_homing = axis->is_cia402();
  c.auto_homing = (axis->axis_mode & kNoAutomaticHoming) == 0 && !c.drive_homing;
  c.drive_speed_scaling = SpeedScaling{axis->speed_increments_num, axis->speed_increments_denom, axis->speed_time_base};
  return c;
}

}  // namespace nck::spindle
