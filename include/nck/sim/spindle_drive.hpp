#pragma once
// The simulated drive behind one spindle (moved here from the spindle
// interpolator: the kernel only judges measured values). Each cycle it takes
// the NC's command (set-point increment, feedforward weight, gear stage) and
// returns its actual speed and position, both on the drive's side of the
// reverse flip, as a real drive would count them.
//
// Position-controlled: P loop with kv; the actual lags v/kv behind, with
// feedforward (G135, weight G136) only a*Ta/kv remains (FCT-S1 2.8.1).
// Speed-controlled (antr.operation_mode OPEN_POSITION_LOOP*): the actual
// speed follows with a first-order lag (sim.lis drive.speed_time_constant_ms).
#include <array>

#include "nck/config/machine.hpp"
#include "nck/core/kept_quotient.hpp"
#include "nck/spindle/drive_io.hpp"

namespace nck::sim {

struct SpindleDriveConfig {
  bool open_loop = false;               // speed-controlled
  double speed_time_constant_s = 0.02;  // speed lag of a speed-controlled drive
  double feedforward_ta_s = 1e-6;       // time constant Ta of the feedforward path
  std::array<double, config::kMaxGearStages> position_gain_1_s{};  // position-loop gain per gear stage
  double cycle_s = 0.001;

  // `axis` may be null (a PLC spindle without an axis list): default gear data. // setup
  static SpindleDriveConfig from(const config::AxisConfig* axis, const config::SimConfig& sim, double cycle_s);
};

class SpindleDrive {
 public:
  SpindleDrive() : SpindleDrive(SpindleDriveConfig{}) {}
  explicit SpindleDrive(const SpindleDriveConfig& cfg);

  // One cycle: the drive follows the command; returns its measured values. // rt
  spindle::DriveFeedback step(const spindle::DriveCommand& cmd) noexcept;

  double lag_deg() const noexcept { return lag_deg_; }  // drive sense

 private:
  SpindleDriveConfig cfg_{};
  // Per cycle: the speed lag's share (open loop), and per gear stage the
  // position loop's gain and its decay over one cycle (computed once).
  double speed_share_ = 1;
  double feedforward_share_ = 1;  // of the commanded speed into the filter, per cycle (backward Euler)
  std::array<double, config::kMaxGearStages> kv_1_s_{}, decay_{};
  KeptQuotient speed_cmd_, lag_share_;  // step / dt and the lag's input / kv, at a steady speed the same
  double lag_deg_ = 0;
  double filtered_vel_deg_s_ = 0;  // commanded speed through the time constant Ta
  double act_vel_deg_s_ = 0;
};

}  // namespace nck::sim
