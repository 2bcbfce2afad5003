// Simulated drive behind the set point, and the status the kernel reads.
// Position-controlled: P loop with kv; the actual lags v/kv behind, with
// feedforward (G135, weight G136) only a*Ta/kv remains (FCT-S1 2.8.1).
// Speed-controlled: the actual speed follows with a first-order lag.
#include <algorithm>
#include <cmath>

#include "nck/spindle/drive_scaling.hpp"
#include "nck/spindle/spindle_axis.hpp"

namespace nck::spindle {

double SpindleAxis::drive_sense() const noexcept { return gear().reverse ? -1.0 : 1.0; }

void SpindleAxis::drive_model(double step_deg, double dt) noexcept {
  // The model runs on the drive's side of the sign flip of getriebe[i].reverse
  // (P-AXIS-00159): the command goes out inverted, the actual comes back
  // inverted (update_status), so the NC sees its own turning sense.
  DriveModel& d = drive_;
  const double v_cmd = drive_sense() * step_deg / dt;  // what the set point really moved this cycle
  if (cfg_.open_loop) {
    const double t = cfg_.speed_time_constant_s;
    const double k = t > 0 ? 1.0 - std::exp(-dt / t) : 1.0;
    d.act_vel_deg_s += (v_cmd - d.act_vel_deg_s) * k;
    d.lag_deg += (v_cmd - d.act_vel_deg_s) * dt;
  } else {
    const double ta = cfg_.feedforward_ta_s;
    const double kf = dt / (ta + dt);  // backward Euler: ramp lag is exactly a*Ta
    d.filtered_vel_deg_s += (v_cmd - d.filtered_vel_deg_s) * kf;  // the drive answers with time constant Ta
    const double w = ff_.on ? ff_.weight : 0.0;
    const double kv = gear().kv_1_s > 0 ? gear().kv_1_s : 10.0;
    // Exact solution of d(lag)/dt = v_cmd - w*v_filt - kv*lag over one cycle:
    // stable for any kv*dt.
    const double e = std::exp(-kv * dt);
    const double lag_new = d.lag_deg * e + (v_cmd - w * d.filtered_vel_deg_s) * (1.0 - e) / kv;
    d.act_vel_deg_s = v_cmd - (lag_new - d.lag_deg) / dt;
    d.lag_deg = lag_new;
  }
  // With the command at rest, the decaying lag and speed are cut to zero once
  // far below any encoder's resolution: the drive then counts as settled
  // (SpindleAxis::at_rest) instead of decaying through denormals forever.
  if (v_cmd == 0 && std::fabs(d.lag_deg) < 1e-12 && std::fabs(d.act_vel_deg_s) < 1e-9 &&
      std::fabs(d.filtered_vel_deg_s) < 1e-9)
    d = DriveModel{};
  if (!std::isfinite(d.lag_deg) || !std::isfinite(d.act_vel_deg_s)) {  // never let NaN out
    d.lag_deg = 0;
    d.act_vel_deg_s = v_cmd;
    d.filtered_vel_deg_s = v_cmd;
  }
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
  const double act_vel_deg_s = drive_sense() * drive_.act_vel_deg_s;
  const double lag_deg = drive_sense() * drive_.lag_deg;
  s.act_rpm = deg_s_to_rpm(act_vel_deg_s);
  s.act_pos_deg = g.wrap(set_.pos_deg - lag_deg);
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
