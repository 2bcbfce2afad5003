#pragma once
// The per-spindle interpolator (FCT-S1 2.3-2.8): one object per spindle,
// configured at setup, then commanded and ticked from the kernel's cyclic
// path. Everything after configure() is noexcept and allocation-free.
//
// Speeds are rpm at the command edge (signed: M3 +, M4 -), deg/s inside;
// positions are degrees in the gear stage's modulo range.
#include <cstdint>
#include <expected>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/spindle/positioning.hpp"
#include "nck/spindle/spindle_params.hpp"
#include "nck/spindle/spindle_status.hpp"

namespace nck::spindle {

// Tool-related limits (wz[i].vb_min / vb_max / a_max); 0 = no limit.
struct ToolDynamics {
  double vb_min_rpm = 0;
  double vb_max_rpm = 0;
  double a_max_deg_s2 = 0;
};

class SpindleAxis {
 public:
  // `axis` may be null for a PLC spindle over the channel HLI (plc_control):
  // it then runs on default gear data. Fails on a non-positive cycle time. // setup
  std::expected<void, Diagnostic> configure(const config::AxisConfig* axis,
                                            const config::ChannelSpindle& sp,
                                            const config::SimConfig& sim, double cycle_s);

  // --- commands (rt) -------------------------------------------------------
  SpindleResult rotate(double rpm, bool g167 = false) noexcept;        // M3 (+) / M4 (-) / S
  SpindleResult stop() noexcept;                                       // M5
  SpindleResult position(double target_deg, Direction dir, double rpm,
                         bool g167 = false) noexcept;                  // M19 [M3|M4] POS REV
  SpindleResult home() noexcept;                                       // G74
  SpindleResult start_gear_change(std::uint32_t stage) noexcept;      // M40..M45 -> 1..6
  SpindleResult finish_gear_change() noexcept;                         // PLC shifted
  SpindleResult load_gear_data(std::uint32_t stage) noexcept;         // G112 (standstill)
  void set_override_pct(double pct) noexcept;                         // HLI, clamped 0..200
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
  SpindleResult enter_axis_mode() noexcept;                           // #CAX, G63 (standstill)
  void axis_set_point(double pos_deg, double vel_deg_s) noexcept;     // per cycle in axis mode
  SpindleResult leave_axis_mode() noexcept;

  // One interpolation cycle of dt_s seconds. // rt
  void tick(double dt_s) noexcept;

  const SpindleStatus& status() const noexcept { return status_; }
  const SpindleParams& params() const noexcept { return p_; }
  bool configured() const noexcept { return configured_; }

 private:
  enum class After : std::uint8_t { none, refpkt, target, stop };

  // commands.cpp
  SpindleResult guard() const noexcept;
  SpindleResult fail(ErrorId id) noexcept;
  void adopt_pending_tool() noexcept;
  void begin_positioning(SpindleMode mode, double target_deg, Direction dir, double speed_deg_s,
                         bool overridable) noexcept;
  void begin_homing(After after, Direction dir) noexcept;
  int preferred() const noexcept;  // +1 / -1 when vorz_richtung, else 0
  bool check_preferred_direction_ok(int dir) const noexcept;
  // dynamics.cpp
  const config::GearStage& gear() const noexcept;
  double accel_limit(double a_deg_s2) const noexcept;
  double accel_up(double speed_deg_s) const noexcept;
  double accel_down(double speed_deg_s) const noexcept;
  double min_accel_down(double up_to_deg_s) const noexcept;
  double max_speed_deg_s() const noexcept;
  double override_factor() const noexcept;
  double limit_speed(double speed_deg_s) const noexcept;
  double range_deg() const noexcept;
  // tick.cpp
  void ramp_to(double target_deg_s, double dt) noexcept;
  void advance(double dv_dt_pos, double dt) noexcept;
  void tick_rotate(double dt) noexcept;
  void tick_position(double dt) noexcept;
  void plan_positioning(double dt) noexcept;
  void step_positioning(double dt) noexcept;
  void tick_homing(double dt) noexcept;
  bool crossed_mark(double from_deg, double step_deg) const noexcept;
  double homing_speed_deg_s() const noexcept;
  double positioning_speed_deg_s() const noexcept;
  void on_reference(double dt) noexcept;
  void finish_positioning() noexcept;
  // drive.cpp
  void drive_model(double step_deg, double dt) noexcept;
  void update_status() noexcept;

  SpindleParams p_{};
  bool configured_ = false;
  SpindleMode mode_ = SpindleMode::stop;
  std::uint32_t gear_ = 1;
  ErrorId error_{};

  // set point
  double pos_deg_ = 0;        // wrapped into the modulo range
  double v_deg_s_ = 0;        // signed set speed
  double a_deg_s2_ = 0;       // last cycle's set acceleration
  double step_deg_ = 0;       // last cycle's position increment

  // speed command
  double programmed_rpm_ = 0;
  double override_pct_ = 100;
  bool ignore_override_ = false;  // G167
  double accel_weight_ = 1.0;     // G130
  bool feedhold_ = false;

  // positioning / homing / gear change approach
  double target_deg_ = 0;
  Direction pos_dir_req_ = Direction::none;  // as commanded
  int pos_dir_ = 0;               // +1 / -1 once planned
  double pos_speed_deg_s_ = 0;    // positioning speed before override
  bool pos_overridable_ = true;
  bool planned_ = false;
  bool pos_done_ = false;
  double remaining_deg_ = 0;      // >= 0 along pos_dir_
  double pos_accel_ = 0;          // braking acceleration of the plan
  double pos_speed_cap_ = 0;      // speed the plan's braking covers
  After after_home_ = After::none;
  bool mark_found_ = false;       // homing: zero mark passed, now positioning
  int home_dir_ = 1;
  double home_target_deg_ = 0;    // M19 target kept while homing first
  Direction home_target_dir_ = Direction::none;
  double home_target_speed_ = 0;
  bool home_target_overridable_ = true;
  std::uint32_t gc_stage_ = 0;    // gear stage being shifted to

  // reference
  bool homed_ = false;
  bool ref_lost_ = false;

  // tool dynamics
  ToolDynamics tool_{};
  ToolDynamics tool_pending_{};
  bool tool_has_pending_ = false;

  // feedforward
  bool ff_on_ = false;
  double ff_weight_ = 1.0;

  // axis mode: what the path interpolator commanded since the last tick
  double axis_step_deg_ = 0;
  double axis_vel_deg_s_ = 0;

  // drive model
  double lag_deg_ = 0;
  double v_filt_deg_s_ = 0;       // set speed through the drive time constant Ta
  double act_v_deg_s_ = 0;

  SpindleStatus status_{};
};

}  // namespace nck::spindle
