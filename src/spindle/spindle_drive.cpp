// Simulated drive behind the set point, and the status the kernel reads.
// Position-controlled: P loop with kv; the actual lags v/kv behind, with
// feedforward (G135, weight G136) only a*Ta/kv remains (FCT-S1 2.8.1).
// Speed-controlled: the actual speed follows with a first-order lag.
#include <algorithm>
#include <cmath>

#include "nck/spindle/drive_scaling.hpp"
#include "nck/spindle/spindle_axis.hpp"

namespace nck::spindle {

void SpindleAxis::drive_model(double step_deg, double dt) noexcept {
  const double v_cmd = step_deg / dt;  // what the set point really moved this cycle
  if (p_.open_loop) {
    const double t = p_.speed_time_constant_s;
    const double k = t > 0 ? 1.0 - std::exp(-dt / t) : 1.0;
    act_v_deg_s_ += (v_cmd - act_v_deg_s_) * k;
    lag_deg_ += (v_cmd - act_v_deg_s_) * dt;
  } else {
    const double ta = p_.feedforward_ta_s;
    const double kf = dt / (ta + dt);  // backward Euler: ramp lag is exactly a*Ta
    v_filt_deg_s_ += (v_cmd - v_filt_deg_s_) * kf;  // the drive answers with time constant Ta
    const double w = ff_on_ ? ff_weight_ : 0.0;
    const double kv = gear().kv_1_s > 0 ? gear().kv_1_s : 10.0;
    // Exact solution of d(lag)/dt = v_cmd - w*v_filt - kv*lag over one cycle:
    // stable for any kv*dt.
    const double e = std::exp(-kv * dt);
    const double lag_new = lag_deg_ * e + (v_cmd - w * v_filt_deg_s_) * (1.0 - e) / kv;
    act_v_deg_s_ = v_cmd - (lag_new - lag_deg_) / dt;
    lag_deg_ = lag_new;
  }
  if (!std::isfinite(lag_deg_) || !std::isfinite(act_v_deg_s_)) {  // never let NaN out
    lag_deg_ = 0;
    act_v_deg_s_ = v_cmd;
    v_filt_deg_s_ = v_cmd;
  }
}

void SpindleAxis::update_status() noexcept {
  SpindleStatus& s = status_;
  const auto& g = gear();
  s.mode = mode_;
  s.gear_stage = gear_;
  s.error = error_;
  s.set_rpm = deg_s_to_rpm(v_deg_s_);
  s.set_pos_deg = pos_deg_;
  s.act_rpm = deg_s_to_rpm(act_v_deg_s_);
  s.act_pos_deg = wrap_modulo(pos_deg_ - lag_deg_, g.modulou, g.moduloo);
  s.lag_deg = lag_deg_;
  s.set_accel_deg_s2 = a_deg_s2_;
  s.programmed_rpm = programmed_rpm_;
  s.override_pct = ignore_override_ ? 100.0 : override_pct_;
  s.feedhold = feedhold_;
  s.homed = homed_;
  s.reference_lost = ref_lost_;
  const bool rotating = mode_ == SpindleMode::rotate;
  s.cmd_rpm = rotating ? deg_s_to_rpm(limit_speed(rpm_to_deg_s(programmed_rpm_) * override_factor())) : 0.0;
  s.standstill = v_deg_s_ == 0 && zero_speed(act_v_deg_s_, g.vb_min_null);
  if (rotating)
    s.speed_reached = s.cmd_rpm == 0 ? s.standstill : speed_reached(s.act_rpm, s.cmd_rpm, p_.vb_prozent_permille);
  else
    s.speed_reached = mode_ == SpindleMode::stop && s.standstill;
  const bool positioning = mode_ == SpindleMode::position || mode_ == SpindleMode::gear_change ||
                           mode_ == SpindleMode::homing;
  s.target_pos_deg = positioning ? target_deg_ : pos_deg_;
  s.distance_to_go_deg = positioning && planned_ ? pos_dir_ * remaining_deg_ : 0.0;
  s.in_position = mode_ == SpindleMode::position && pos_done_ &&
                  std::fabs(lag_deg_) <= p_.in_position_window_deg;
  s.gear_change_ready = mode_ == SpindleMode::gear_change && pos_done_ && s.standstill;
  const double out_rpm = p_.open_loop ? s.set_rpm : s.act_rpm;
  s.drive_output = drive_output_value(p_.v_reso_num, p_.v_reso_denom, p_.v_time_base, out_rpm, p_.cycle_s);
}

}  // namespace nck::spindle
