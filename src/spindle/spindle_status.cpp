// The spindle's side of its drive: the command that goes out, the measured
// actual values that come back, and the status the kernel reads, judged
// from those values against the set point and the tolerances.
#include <cmath>

#include "nck/spindle/drive_scaling.hpp"
#include "nck/spindle/spindle_axis.hpp"

namespace nck::spindle {

double SpindleAxis::drive_sense() const noexcept { return gear().reverse_sense ? -1.0 : 1.0; }

DriveCommand SpindleAxis::drive_command() const noexcept {
  // getriebe[i].reverse (P-AXIS-00159): the command goes out inverted, the
  // actual values come back inverted (update_status), so the NC sees its
  // own turning sense.
  const double sense = drive_sense();
  return DriveCommand{sense * set_.step_deg, sense * set_.pos_deg, ff_.on ? ff_.weight : 0.0, gear_};
}

void SpindleAxis::take_feedback(const DriveFeedback& feedback) noexcept {
  feedback_ = feedback;
  update_status();
}

void SpindleAxis::update_status() noexcept {
  SpindleStatus& s = status_;
  const auto& g = gear();
  s.mode = mode_;
  s.gear_stage = gear_;
  s.error = error_;
  s.set_rpm = deg_s_to_rpm(set_.vel_deg_s);
  s.set_pos_deg = set_.pos_deg;
  // Actual values as the NC reads them: back through the reverse flip.
  // Nothing measured: the set point stands for the actual value.
  const bool measured = feedback_.valid;
  const double act_vel_deg_s = measured ? drive_sense() * feedback_.actual_speed_deg_s : set_.vel_deg_s;
  const double act_pos_deg = measured ? drive_sense() * feedback_.actual_pos_deg : set_.pos_deg;
  // The following error, the short way round the modulo range.
  double lag_deg = set_.pos_deg - act_pos_deg;
  if (const double half = g.range_deg() / 2; !(std::fabs(lag_deg) <= half))
    lag_deg = wrap_modulo(lag_deg, -half, half);
  s.act_rpm = deg_s_to_rpm(act_vel_deg_s);
  s.act_pos_deg = g.wrap(act_pos_deg);
  s.lag_deg = lag_deg;
  s.set_accel_deg_s2 = set_.accel_deg_s2;
  s.programmed_rpm = speed_.programmed_rpm;
  s.override_pct = speed_.ignore_override ? 100.0 : speed_.override_pct;
  s.feedhold = speed_.feedhold;
  s.homed = ref_.homed;
  s.reference_lost = ref_.lost;
  const bool rotating = mode_ == SpindleMode::rotate;
  s.cmd_rpm =
      rotating ? deg_s_to_rpm(rotation_speed_deg_s()) : 0.0;
  // The speed the acknowledgements judge: a sensorless spindle has only its
  // own command value (FCT-S1 2.2.4), the others their actual speed.
  const double ack_vel_deg_s = cfg_.sensorless ? set_.vel_deg_s : act_vel_deg_s;
  s.standstill = set_.vel_deg_s == 0 && zero_speed(ack_vel_deg_s, g.zero_speed_deg_s);
  if (rotating)
    s.speed_reached = s.cmd_rpm == 0 ? s.standstill
                                     : speed_reached(deg_s_to_rpm(ack_vel_deg_s), s.cmd_rpm,
                                                     cfg_.speed_reached_tolerance_permille);
  else
    s.speed_reached = mode_ == SpindleMode::stop && s.standstill;
  const bool positioning = mode_ == SpindleMode::position || mode_ == SpindleMode::gear_change ||
                           mode_ == SpindleMode::homing;
  s.target_pos_deg = positioning ? pos_.target_deg : set_.pos_deg;
  s.distance_to_go_deg = positioning && pos_.planned ? pos_.dir * pos_.remaining_deg : 0.0;
  s.in_position = mode_ == SpindleMode::position && pos_.done &&
                  std::fabs(lag_deg) <= cfg_.in_position_window_deg;
  s.gear_change_ready = mode_ == SpindleMode::gear_change && pos_.done && s.standstill;
  const double out_rpm = cfg_.open_loop ? s.set_rpm : s.act_rpm;
  s.drive_output = drive_output_value(cfg_.drive_speed_scaling, drive_sense() * out_rpm, cfg_.cycle_s);
}

}  // namespace nck::spindle
