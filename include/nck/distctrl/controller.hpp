#pragma once
// 3D distance control of one channel (channel_params_distctrl seed;
// docs/nc-language.md): the state
// machine, and per cycle the chain sensor -> range and rate monitoring ->
// filter -> ref_offset -> PID -> limiter -> max_deviation. Its output is the
// offset the channel adds to the tool axis. Fixed-size, no allocation; the
// cyclic calls are noexcept.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/distctrl/filters.hpp"
#include "nck/distctrl/limiter.hpp"
#include "nck/distctrl/pid.hpp"

namespace nck::distctrl {

// The values are the order of the TF5200 list (INACTIVE = 0, ACTIVE = 1;
// the rest is our numbering, docs/decisions.md, "3D distance control").
enum class State : std::uint8_t { inactive = 0, active = 1, active_const = 2, freeze = 3, turning_off = 4, error = 5 };
std::string_view state_name(State s) noexcept;

inline constexpr double kKeep = std::numeric_limits<double>::quiet_NaN();

// The settings in force: the channel list's, with the NC overrides on top.
struct Settings {
  FilterSettings filter{};
  double kp = 1, i_tn_s = 0, d_tv_s = 0;
  LimiterSettings limiter{};
  double max_deviation_mm = 5;
  double ref_offset_mm = 0;
  double min_pos_mm = -5, max_pos_mm = 5, tolerance_mm = 0;
  double max_act_value_change_mm_s = 5;  // 0 = not monitored
};
Settings settings_from(const config::DistCtrlConfig& c);  // setup

// One #DIST CTRL command as planned: fixed-size (it travels in the command
// queue). NaN / -1 leave a value as it is.
enum class Op : std::uint8_t { none, on, freeze, off };
struct Switch {
  Op op = Op::none;
  bool const_dist = false;
  bool no_move = false;  // OFF NO_MOVE: off at once, the offset stays
  double set_pos_mm = kKeep, set_dist_mm = kKeep;
  double kp = kKeep, i_tn_s = kKeep, d_tv_s = kKeep, f0_hz = kKeep, smoothing = kKeep, kalman_sigma = kKeep;
  std::int16_t n_cycles = -1, order = -1;
  std::int8_t filter = -1;  // FilterKind
  bool any() const noexcept;
};

struct Sample {
  bool valid = false;  // false: no value this cycle (a dropout)
  double value_mm = 0; // raw sensor value
};

class Controller {
 public:
  void setup(const Settings& s, double dt_s) noexcept;  // setup, and at program end / reset

  // A #DIST CTRL command; returns an error ID (310024, 310025) or {}.
  ErrorId apply(const Switch& sw) noexcept;
  // One cycle: the tool axis's programmed set point (surface mode) and the
  // sensor sample. Returns an error ID when a monitor trips (the state is
  // then ERROR and the offset held), else {}.
  ErrorId step(const Sample& s, double prog_tool_mm) noexcept;
  // Program end / abort / reset: INACTIVE at once with the offset where it
  // is (ERROR stays visible); `clear` also forgets SET_POS and overrides.
  void stop(bool clear) noexcept;

  State state() const noexcept { return state_; }
  bool engaged() const noexcept { return state_ != State::inactive && state_ != State::error; }
  double offset_mm() const noexcept { return limiter_.pos(); }
  double offset_v_mm_s() const noexcept { return limiter_.v(); }
  double sensor_mm() const noexcept { return sensor_mm_; }
  double dist_error_mm() const noexcept { return dist_error_mm_; }
  const Settings& settings() const noexcept { return s_; }
  // The offset limit was reached (P-CHAN-00801): clamp and error.
  ErrorId clamp_to(double lo_mm, double hi_mm) noexcept;

 private:
  ErrorId check_range(double raw_mm) const noexcept;
  ErrorId fail(ErrorId id) noexcept;
  void configure_chain() noexcept;

  Settings base_{}, s_{};
  double dt_s_ = 0.001;
  State state_ = State::inactive;
  bool const_mode_ = false;
  double set_pos_mm_ = kKeep, set_dist_mm_ = 0;
  SensorFilter filter_;
  Pid pid_;
  Limiter limiter_;
  bool restart_ = true;  // the filter starts from the next sample
  double last_filtered_mm_ = 0;
  double sensor_mm_ = 0, dist_error_mm_ = 0;
  double target_mm_ = 0;
};

}  // namespace nck::distctrl
