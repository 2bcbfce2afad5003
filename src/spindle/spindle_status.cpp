// The spindle's side of its drive: the command that goes out, the measured
// actual values that come back, and the status the kernel reads, judged
// from those values against the set point and the tolerances.
#include <cassert>
#include <cmath>

#include "nck/spindle/drive_scaling.hpp"
#include "nck/spindle/spindle_axis.hpp"

namespace nck::spindle {

void SpindleAxis::take_feedback(const DriveFeedback& feedback) noexcept {
  feedback_ = feedback;  // not a change of commands or state: the speeds are compared
  update_status();
}

void SpindleAxis::update_status() noexcept {
  SpindleStatus& s = status_;
  const auto& g = gear();
  // Actual values as the NC reads them: back through the reverse flip.
  // Nothing measured: the set point stands for the actual value.
  const bool measured = feedback_.valid;
  const double act_vel_deg_s = measured ? drive_sense() * feedback_.actual_speed_deg_s : set_.vel_deg_s;
  const double act_pos_deg = measured ? drive_sense() * feedback_.actual_pos_deg : set_.pos_deg;
  // At a steady speed (most cycles of a turning spindle) nothing the speed
  // judgement depends on changes, and only positions are new.
  if (!(judged_.epoch == epoch_ && judged_.set_vel_deg_s == set_.vel_deg_s &&
        judged_.set_accel_deg_s2 == set_.accel_deg_s2 && judged_.act_vel_deg_s == act_vel_deg_s)) {
    judged_inputs_ = status_inputs(act_vel_deg_s);
    judge_speed(judged_inputs_);
    judged_ = Judged{epoch_, set_.vel_deg_s, set_.accel_deg_s2, act_vel_deg_s};
  }
  assert(std::isnan(act_vel_deg_s) || judged_inputs_ == status_inputs(act_vel_deg_s));  // they change only with epoch_
  s.set_pos_deg = set_.pos_deg;
  // The following error, the short way round the modulo range.
  double lag_deg = set_.pos_deg - act_pos_deg;
  if (const double half = g.range_deg() / 2; !(std::fabs(lag_deg) <= half))
    lag_deg = wrap_modulo(lag_deg, -half, half);
  s.act_pos_deg = g.wrap(act_pos_deg);
  s.lag_deg = lag_deg;
  const bool positioning = mode_ == SpindleMode::position || mode_ == SpindleMode::gear_change ||
                           mode_ == SpindleMode::homing;
  s.target_pos_deg = positioning ? pos_.target_deg : set_.pos_deg;
  s.distance_to_go_deg = positioning && pos_.planned ? pos_.dir * pos_.remaining_deg : 0.0;
  s.in_position = mode_ == SpindleMode::position && pos_.done &&
                  std::fabs(lag_deg) <= cfg_.in_position_window_deg;
  s.gear_change_ready = mode_ == SpindleMode::gear_change && pos_.done && s.standstill;
}

SpindleAxis::StatusInputs SpindleAxis::status_inputs(double act_vel_deg_s) const noexcept {
  const bool rotating = mode_ == SpindleMode::rotate;
  return StatusInputs{mode_,
                      gear_,
                      error_,
                      set_.vel_deg_s,
                      set_.accel_deg_s2,
                      act_vel_deg_s,
                      speed_.programmed_rpm,
                      speed_.override_pct,
                      rotating ? rotation_speed_deg_s() : 0.0,
                      speed_.ignore_override,
                      speed_.feedhold,
                      ref_.homed,
                      ref_.lost};
}

// The status fields that follow from the speeds, the commands and the state.
void SpindleAxis::judge_speed(const StatusInputs& in) noexcept {
  ++judgements_;
  SpindleStatus& s = status_;
  const auto& g = gear();
  s.mode = in.mode;
  s.gear_stage = in.gear;
  s.error = in.error;
  s.set_rpm = deg_s_to_rpm(in.set_vel_deg_s);
  s.act_rpm = deg_s_to_rpm(in.act_vel_deg_s);
  s.set_accel_deg_s2 = in.set_accel_deg_s2;
  s.programmed_rpm = in.programmed_rpm;
  s.override_pct = in.ignore_override ? 100.0 : in.override_pct;
  s.feedhold = in.feedhold;
  s.homed = in.homed;
  s.reference_lost = in.reference_lost;
  const bool rotating = in.mode == SpindleMode::rotate;
  s.cmd_rpm = rotating ? deg_s_to_rpm(in.rotation_deg_s) : 0.0;
  // The speed the acknowledgements judge: a sensorless spindle has only its
  // own command value (FCT-S1 2.2.4), the others their actual speed.
  const double ack_vel_deg_s = cfg_.sensorless ? in.set_vel_deg_s : in.act_vel_deg_s;
  s.standstill = in.set_vel_deg_s == 0 && zero_speed(ack_vel_deg_s, g.zero_speed_deg_s);
  if (rotating)
    s.speed_reached = s.cmd_rpm == 0 ? s.standstill
                                     : speed_reached(deg_s_to_rpm(ack_vel_deg_s), s.cmd_rpm,
                                                     cfg_.speed_reached_tolerance_permille);
  else
    s.speed_reached = in.mode == SpindleMode::stop && s.standstill;
  const double out_rpm = cfg_.open_loop ? s.set_rpm : s.act_rpm;
  s.drive_output = drive_output_value(cfg_.drive_speed_scaling, drive_sense() * out_rpm, cfg_.cycle_s);
}

}  // namespace nck::spindle
