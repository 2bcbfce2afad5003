#include "nck/sim/spindle_drive.hpp"

#include <algorithm>
#include <cmath>

namespace nck::sim {

SpindleDriveConfig SpindleDriveConfig::from(const config::AxisConfig* axis, const config::SimConfig& sim,
                                            double cycle_s) {
  SpindleDriveConfig c;
  c.cycle_s = cycle_s;
  c.speed_time_constant_s = std::max(0.0, sim.drive_speed_time_constant_s);
  const auto stages = axis != nullptr ? axis->gears : decltype(axis->gears){};
  for (std::size_t i = 0; i < stages.size(); ++i) c.position_gain_1_s[i] = stages[i].position_gain_1_s;
  if (axis == nullptr) return c;
  c.open_loop = axis->is_speed_controlled();
  c.feedforward_ta_s = std::max(0.0, axis->feedforward_ta_s);
  return c;
}

SpindleDrive::SpindleDrive(const SpindleDriveConfig& cfg) : cfg_(cfg) {
  const double dt = cfg_.cycle_s;
  const double t = cfg_.speed_time_constant_s;
  speed_share_ = t > 0 ? 1.0 - std::exp(-dt / t) : 1.0;
  feedforward_share_ = dt / (cfg_.feedforward_ta_s + dt);  // backward Euler: ramp lag is exactly a*Ta
  for (std::size_t g = 0; g < kv_1_s_.size(); ++g) {
    kv_1_s_[g] = cfg_.position_gain_1_s[g] > 0 ? cfg_.position_gain_1_s[g] : 10.0;
    decay_[g] = std::exp(-kv_1_s_[g] * dt);
  }
}

spindle::DriveFeedback SpindleDrive::step(const spindle::DriveCommand& cmd) noexcept {
  const double dt = cfg_.cycle_s;
  const double v_cmd = speed_cmd_.divide(cmd.step_deg, dt);  // what the set point really moved this cycle
  if (cfg_.open_loop) {
    act_vel_deg_s_ += (v_cmd - act_vel_deg_s_) * speed_share_;
    lag_deg_ += (v_cmd - act_vel_deg_s_) * dt;
  } else {
    filtered_vel_deg_s_ += (v_cmd - filtered_vel_deg_s_) * feedforward_share_;  // the drive answers with time constant Ta
    const double w = cmd.feedforward_weight;
    const std::uint32_t g = cmd.gear_stage >= 1 && cmd.gear_stage <= config::kMaxGearStages ? cmd.gear_stage - 1 : 0;
    const double kv = kv_1_s_[g];
    // Exact solution of d(lag)/dt = v_cmd - w*v_filt - kv*lag over one cycle:
    // stable for any kv*dt.
    const double e = decay_[g];
    const double lag_new = lag_deg_ * e + lag_share_.divide((v_cmd - w * filtered_vel_deg_s_) * (1.0 - e), kv);
    // A lag that stays (a steady speed) leaves the actual speed the commanded one.
    const double lag_change = lag_new - lag_deg_;
    act_vel_deg_s_ = lag_change == 0 && v_cmd != 0 ? v_cmd : v_cmd - lag_change / dt;
    lag_deg_ = lag_new;
  }
  // With the command at rest, the decaying lag and speed are cut to zero once
  // far below any encoder's resolution: the drive then reports exactly no
  // speed and no following error, and the spindle counts as settled
  // (SpindleAxis::at_rest) instead of decaying through denormals forever.
  if (v_cmd == 0 && std::fabs(lag_deg_) < 1e-12 && std::fabs(act_vel_deg_s_) < 1e-9 &&
      std::fabs(filtered_vel_deg_s_) < 1e-9)
    lag_deg_ = act_vel_deg_s_ = filtered_vel_deg_s_ = 0;
  if (!std::isfinite(lag_deg_) || !std::isfinite(act_vel_deg_s_)) {  // never let NaN out
    lag_deg_ = 0;
    act_vel_deg_s_ = v_cmd;
    filtered_vel_deg_s_ = v_cmd;
  }
  return spindle::DriveFeedback{act_vel_deg_s_, cmd.pos_deg - lag_deg_, true};
}

}  // namespace nck::sim
