#pragma once
// The per-spindle interpolator (FCT-S1 2.3-2.8): one object per spindle,
// configured at setup, then commanded and ticked from the kernel's cyclic
// path. Everything after configure() is noexcept and allocation-free.
//
// It makes the set point and judges the drive's measured actual values
// (take_feedback); the drive itself is not part of it (nck/sim simulates
// one, a real machine has its own).
//
// Speeds are rpm at the command edge (signed: M3 +, M4 -), deg/s inside;
// positions are degrees in the gear stage's modulo range.
#include <cstdint>
#include <optional>
#include <expected>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/spindle/drive_io.hpp"
#include "nck/spindle/positioning.hpp"
#include "nck/spindle/spindle_config.hpp"
#include "nck/spindle/spindle_state.hpp"
#include "nck/spindle/spindle_status.hpp"

namespace nck::spindle {

class SpindleAxis {
 public:
  // `axis` may be null for a PLC spindle over the channel HLI (plc_control):
  // it then runs on default gear data. Fails on a non-positive cycle time. // setup
  std::expected<void, Diagnostic> configure(const config::AxisConfig* axis,
                                            const config::ChannelSpindle& sp, double cycle_s);

  // --- commands (rt) -------------------------------------------------------
  SpindleResult rotate(double rpm, bool g167 = false) noexcept;        // M3 (+) / M4 (-) / S
  SpindleResult stop() noexcept;                                       // M5
  SpindleResult position(double target_deg, Direction dir, double rpm,
                         bool g167 = false) noexcept;                  // M19 [M3|M4] POS REV
  SpindleResult home() noexcept;                                       // G74
  SpindleResult start_gear_change(std::uint32_t stage) noexcept;      // M40..M45 -> 1..6
  SpindleResult finish_gear_change() noexcept;                         // PLC shifted
  SpindleResult load_gear_data(std::uint32_t stage) noexcept;         // G112 (standstill)
  void set_override_pct(double pct) noexcept {                       // HLI, clamped 0..200
    if (pct != speed_.override_pct) change_override_pct(pct);          // the PLC writes it every cycle
  }
  void suppress_override() noexcept;                                  // G167 alone
  SpindleResult set_accel_weight_pct(double pct) noexcept;            // G130
  SpindleResult feedforward_on() noexcept;                            // G135
  SpindleResult feedforward_weight_pct(double pct) noexcept;          // G136 (0..100)
  SpindleResult feedforward_off() noexcept;                           // G137
  void set_tool_dynamics(const ToolDynamics& t) noexcept;             // D / #TOOL DATA: pending
  SpindleResult adopt_tool_dynamics_now() noexcept;                   // GET_DYNAMIC_DATA
  SpindleResult default_dynamic_data() noexcept;                      // DEFAULT_DYNAMIC_DATA
  void set_feedhold(bool on) noexcept;                                // HLI feedhold
  void reset() noexcept;                                              // channel reset
  void abort() noexcept;                                              // NC-error abort: keeps an error state
  // E-stop / machine off: brakes to standstill with its ramp whatever
  // P-AXIS-00455 says; an error state stays, axis mode (#CAX) follows its path.
  void halt() noexcept;
  SpindleResult enter_axis_mode() noexcept;                           // #CAX, G63 (standstill)
  void axis_set_point(double pos_deg, double vel_deg_s) noexcept;     // per cycle in axis mode
  SpindleResult leave_axis_mode() noexcept;

  // One interpolation cycle of dt_s seconds: the set point moves, and the
  // status follows with the last feedback (refresh_status false: a drive
  // answers within this cycle and its take_feedback updates the status
  // once). False when the spindle is at rest (stopped, its drive settled):
  // nothing changed, the drive needs no new command. // rt
  bool tick(double dt_s, bool refresh_status = true) noexcept;
  // What the drive gets for the cycle just ticked (drive sense). // rt
  // getriebe[i].reverse (P-AXIS-00159): the command goes out inverted, the
  // actual values come back inverted (update_status), so the NC sees its
  // own turning sense. Inline: every spindle, every cycle.
  DriveCommand drive_command() const noexcept {
    const double sense = drive_sense();
    return DriveCommand{sense * set_.step_deg, sense * set_.pos_deg, ff_.on ? ff_.weight : 0.0, gear_};
  }
  // The following error of the last cycle's set point, drive sense: that
  // set point (this cycle's less its step) minus the measured position. A
  // conventional drive's position loop closes on it. // rt
  double drive_following_error_deg() const noexcept {
    return drive_sense() * status_.lag_deg - drive_command().step_deg;
  }
  // The drive's measured actual values (drive sense); the status (actual
  // speed and position, speed reached, standstill, in position) follows
  // from them and the set point. Invalid feedback: the set point counts as
  // the actual value. // rt
  void take_feedback(const DriveFeedback& feedback) noexcept;
  const DriveFeedback& feedback() const noexcept { return feedback_; }
  // Drive-controlled homing (config().drive_homing): G74 brings the set
  // point to a stop, then the spindle waits for its drive to home. // rt
  bool awaits_drive_homing() const noexcept {
    return mode_ == SpindleMode::homing && cfg_.drive_homing && set_.vel_deg_s == 0;
  }
  // The drive homed and stands at drive_pos_deg (drive sense): the
  // spindle is homed there and stops. // rt
  void drive_homed(double drive_pos_deg) noexcept;

  const SpindleStatus& status() const noexcept { return status_; }
  // How often the speed part of the status (mode, speeds, speed reached,
  // standstill...) was judged: unchanged, so is that part. // rt
  std::uint64_t judgements() const noexcept { return judgements_; }
  const SpindleConfig& config() const noexcept { return cfg_; }
  bool configured() const noexcept { return configured_; }

 private:
  void change_override_pct(double pct) noexcept;
  // commands.cpp
  SpindleResult guard() const noexcept;
  SpindleResult fail(ErrorId id) noexcept;
  void adopt_pending_tool() noexcept;
  void begin_positioning(SpindleMode mode, double target_deg, Direction dir, double speed_deg_s,
                         bool overridable) noexcept;
  void begin_homing(AfterHoming after, Direction dir) noexcept;
  Direction shorter_way(double target_deg) const noexcept;
  // dynamics.cpp
  const GearConfig& gear() const noexcept {  // asked for many times a cycle: inline
    const std::uint32_t i = gear_ >= 1 && gear_ <= config::kMaxGearStages ? gear_ - 1 : 0;
    return cfg_.gears[i];
  }
  double accel_limit(double a_deg_s2) const noexcept;
  double accel_up(double speed_deg_s) const noexcept;
  double accel_down(double speed_deg_s) const noexcept;
  double min_accel_down(double up_to_deg_s) const noexcept;
  double max_speed_deg_s() const noexcept;
  double override_factor() const noexcept;
  double limit_speed(double speed_deg_s) const noexcept;           // max_speed_mm_s caps
  double limit_rotation_speed(double speed_deg_s) const noexcept;  // + tool vb_min (M3/M4 only)
  double rotation_speed_deg_s() const noexcept;  // programmed x override, limited, signed (memo)
  double compute_rotation_speed_deg_s() const noexcept;
  // jerk.cpp: slope_type TRAPEZ / SIN2
  bool jerk_limited_slope() const noexcept { return jerk_limited(gear().slope); }
  motion::JerkLimits jerk_limits() const noexcept;
  void jerk_ramp_to(double target_deg_s, double dt) noexcept;
  void jerk_step_positioning(double dt) noexcept;
  void plan_positioning_ramp(double remaining_deg, double v_cap_deg_s, const motion::JerkLimits& lim) noexcept;
  double jerk_stop_distance_deg(double speed_deg_s, int dir) const noexcept;
  void follow_jerk_plan(double dt, double end_deg_s) noexcept;
  bool jerk_plan_settling(double goal_deg_s) const noexcept;
  bool jerk_finish_speed_ramp(double dt) noexcept;
  // Marks a change of commands or state on entry and on every way out, so
  // that a cruise (below) and the judged speed status end with it.
  struct Changed {
    explicit Changed(SpindleAxis& a) noexcept : axis(a) { ++axis.epoch_; }
    ~Changed() { ++axis.epoch_; }
    Changed(const Changed&) = delete;
    Changed& operator=(const Changed&) = delete;
    SpindleAxis& axis;
  };
  // tick.cpp
  bool tick_all(double dt) noexcept;
  void cruise(double dt) noexcept;
  bool ramp_to(double target_deg_s, double dt) noexcept;
  void advance(double step_deg) noexcept;
  bool at_rest() const noexcept;
  bool tick_rotate(double dt) noexcept;
  void tick_position(double dt) noexcept;
  void plan_positioning(double dt) noexcept;
  void step_positioning(double dt) noexcept;
  void tick_homing(double dt) noexcept;
  bool crossed_mark(double from_deg, double step_deg) const noexcept;
  double homing_speed_deg_s() const noexcept;
  double positioning_speed_deg_s() const noexcept;
  void on_reference() noexcept;
  // spindle_status.cpp
  double drive_sense() const noexcept { return gear().reverse_sense ? -1.0 : 1.0; }  // getriebe[i].reverse
  // What the speed part of the status follows from (update_status judges
  // it anew only when one of them changed).
  struct StatusInputs {
    SpindleMode mode = SpindleMode::stop;
    std::uint32_t gear = 1;
    ErrorId error{};
    double set_vel_deg_s = 0, set_accel_deg_s2 = 0, act_vel_deg_s = 0;
    double programmed_rpm = 0, override_pct = 0, rotation_deg_s = 0;
    bool ignore_override = false, feedhold = false, homed = false, reference_lost = false;
    bool operator==(const StatusInputs&) const = default;
  };
  StatusInputs status_inputs(double act_vel_deg_s) const noexcept;
  void update_status() noexcept;
  void judge_speed(const StatusInputs& in) noexcept;

  SpindleConfig cfg_{};
  bool configured_ = false;
  SpindleMode mode_ = SpindleMode::stop;
  std::uint32_t gear_ = 1;
  ErrorId error_{};

  SetPoint set_{};
  SpeedCommand speed_{};
  Positioning pos_{};
  Homing homing_{};
  Reference ref_{};
  ToolLimits tool_{};
  Feedforward ff_{};
  JerkRamp jerk_{};
  AxisModeInput axis_{};
  DriveFeedback feedback_{};  // the drive's last measured values (drive sense)

  SpindleStatus status_{};
  // rotation_speed_deg_s() for the inputs it saw last: asked for twice a
  // cycle, while its inputs change rarely.
  struct RotationInputs {
    double programmed_rpm = 0, override_pct = 0, tool_min_rpm = 0, tool_max_rpm = 0;
    bool ignore_override = false;
    std::uint32_t gear = 0;
    bool operator==(const RotationInputs&) const = default;
  };
  mutable std::optional<RotationInputs> rotation_seen_;
  mutable double rotation_deg_s_ = 0;
  // The speed status follows from the commands and state, which change only
  // with epoch_, and three speeds: it is judged anew when one of them moved.
  struct Judged {
    std::uint64_t epoch = ~0ull;
    double set_vel_deg_s = 0, set_accel_deg_s2 = 0, act_vel_deg_s = 0;
  };
  Judged judged_{};
  StatusInputs judged_inputs_{};  // what was judged: debug builds check that only epoch_ changes it
  std::uint64_t judgements_ = 0;
  // Bumped by every command and every tick that is not a cruise. A spindle
  // found turning at its commanded speed (not jerk-limited) cruises while
  // epoch_ stays cruise_epoch_: its ticks only advance the position, the
  // same arithmetic the whole tick does then (checked in debug builds).
  std::uint64_t epoch_ = 0;
  std::uint64_t cruise_epoch_ = ~0ull;
};

}  // namespace nck::spindle
