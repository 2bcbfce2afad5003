#include "nck/distctrl/controller.hpp"

#include <algorithm>

namespace nck::distctrl {

std::string_view state_name(State s) noexcept {
  switch (s) {
    case State::inactive: return "INACTIVE";
    case State::active: return "ACTIVE";
    case State::active_const: return "ACTIVE_CONST";
    case State::freeze: return "FREEZE";
    case State::turning_off: return "TURNING_OFF";
    case State::error: return "ERROR";
  }
  return "INACTIVE";
}

Settings settings_from(const config::DistCtrlConfig& c) {
  Settings s;
  s.filter.kind = static_cast<FilterKind>(std::min<int>(static_cast<int>(c.filter_type), 5));
  s.filter.n_cycles = c.n_cycles;
  s.filter.low_pass_enable = c.low_pass_filter_enable;
  s.filter.order = c.low_pass_filter_order;
  s.filter.f0_hz = c.low_pass_filter_fg_f0_hz;
  s.filter.smoothing = c.smoothing_factor;
  s.filter.kalman_sigma = c.kalman_sigma;
  s.kp = c.kp;
  s.i_tn_s = c.i_tn_s;
  s.d_tv_s = c.d_tv_s;
  s.limiter = {c.v_max_mm_s, c.a_max_mm_s2, c.v_weight_down, c.a_weight_down, c.use_adaptive_acceleration,
               c.a_min_mm_s2, c.dist_error_a_min_mm, c.dist_error_a_max_mm};
  s.max_deviation_mm = c.max_deviation_mm;
  s.ref_offset_mm = c.ref_offset_mm;
  s.min_pos_mm = c.min_pos_mm;
  s.max_pos_mm = c.max_pos_mm;
  s.tolerance_mm = c.tolerance_mm;
  s.max_act_value_change_mm_s = c.max_act_value_change_mm_s;
  return s;
}

bool Switch::any() const noexcept {
  return op != Op::none || !std::isnan(set_pos_mm) || !std::isnan(set_dist_mm) || !std::isnan(kp) ||
         !std::isnan(i_tn_s) || !std::isnan(d_tv_s) || !std::isnan(f0_hz) || !std::isnan(smoothing) ||
         !std::isnan(kalman_sigma) || n_cycles >= 0 || order >= 0 || filter >= 0;
}

void Controller::setup(const Settings& s, double dt_s) noexcept {
  base_ = s;
  s_ = s;
  dt_s_ = dt_s;
  configure_chain();
  limiter_.reset(0);
}

void Controller::configure_chain() noexcept {
  filter_.setup(s_.filter, dt_s_);
  pid_.setup(s_.kp, s_.i_tn_s, s_.d_tv_s, dt_s_);
  limiter_.setup(s_.limiter, dt_s_);
  restart_ = true;
}

ErrorId Controller::apply(const Switch& sw) noexcept {
  auto take = [](double v, double& into) {
    if (!std::isnan(v)) into = v;
  };
  take(sw.kp, s_.kp);
  take(sw.i_tn_s, s_.i_tn_s);
  take(sw.d_tv_s, s_.d_tv_s);
  take(sw.f0_hz, s_.filter.f0_hz);
  take(sw.smoothing, s_.filter.smoothing);
  take(sw.kalman_sigma, s_.filter.kalman_sigma);
  if (sw.n_cycles >= 0) s_.filter.n_cycles = static_cast<std::uint32_t>(sw.n_cycles);
  if (sw.order >= 0) s_.filter.order = static_cast<std::uint32_t>(sw.order);
  if (sw.filter >= 0) s_.filter.kind = static_cast<FilterKind>(sw.filter);
  take(sw.set_pos_mm, set_pos_mm_);
  take(sw.set_dist_mm, set_dist_mm_);
  // New filter / controller values take effect from the next sample on;
  // the offset and its velocity carry on (no jump in the set point).
  configure_chain();
  switch (sw.op) {
    case Op::none: return {};
    case Op::on: {
      const bool on = state_ == State::active || state_ == State::active_const;
      if (on && sw.const_dist != const_mode_) return ErrorId::NcDistCtrlModeChange;
      if (!sw.const_dist && std::isnan(set_pos_mm_)) return ErrorId::NcDistCtrlNoSetPos;
      const_mode_ = sw.const_dist;
      if (!on) pid_.reset();
      state_ = const_mode_ ? State::active_const : State::active;
      return {};
    }
    case Op::freeze:
      if (engaged()) state_ = State::freeze;
      return {};
    case Op::off:
      if (!engaged()) return {};
      state_ = sw.no_move ? State::inactive : State::turning_off;
      return {};
  }
  return {};
}

ErrorId Controller::fail(ErrorId id) noexcept {
  state_ = State::error;
  limiter_.hold_at(limiter_.pos());
  return id;
}

// The raw value must stay inside min_pos..max_pos narrowed by the tolerance
// band (P-CHAN-00806..00808): above -> 310019, below -> 310020.
ErrorId Controller::check_range(double raw_mm) const noexcept {
  if (raw_mm > s_.max_pos_mm - s_.tolerance_mm) return ErrorId::DistCtrlSensorAbove;
  if (raw_mm < s_.min_pos_mm + s_.tolerance_mm) return ErrorId::DistCtrlSensorBelow;
  return {};
}

ErrorId Controller::step(const Sample& smp, double prog_tool_mm) noexcept {
  if (!engaged()) return {};
  const bool controlling = state_ == State::active || state_ == State::active_const;
  if (smp.valid) {
    sensor_mm_ = smp.value_mm;
    if (controlling)
      if (ErrorId e = check_range(smp.value_mm); e != ErrorId{}) return fail(e);
    if (restart_) {
      filter_.reset(smp.value_mm);
      last_filtered_mm_ = smp.value_mm;
      restart_ = false;
    }
    const double f = filter_.step(smp.value_mm);
    const double rate = std::fabs(f - last_filtered_mm_) / dt_s_;
    last_filtered_mm_ = f;
    if (controlling && s_.max_act_value_change_mm_s > 0 && rate > s_.max_act_value_change_mm_s)
      return fail(ErrorId::DistCtrlSensorRate);
    const double dist_mm = f - s_.ref_offset_mm;
    const double want_mm = const_mode_ ? set_dist_mm_ : prog_tool_mm - set_pos_mm_;
    dist_error_mm_ = want_mm - dist_mm;
    if (controlling) target_mm_ = limiter_.pos() + pid_.step(dist_error_mm_);
  }
  // FREEZE, and a dropout (no valid sample this cycle), hold the offset
  // where it is (braking within a_max from its velocity). After a dropout
  // the filter starts again from the first new value: what changed
  // meanwhile is no rate of change of the sensor.
  if (state_ == State::freeze || !smp.valid) target_mm_ = limiter_.pos();
  if (!smp.valid) restart_ = true;
  if (state_ == State::turning_off) target_mm_ = 0;
  const double pos = limiter_.step(target_mm_, dist_error_mm_);
  if (std::fabs(pos) > s_.max_deviation_mm) {
    limiter_.hold_at(std::clamp(pos, -s_.max_deviation_mm, s_.max_deviation_mm));
    return fail(ErrorId::DistCtrlMaxDeviation);
  }
  // Rounding may leave a few nm: that is home.
  if (state_ == State::turning_off && std::fabs(limiter_.pos()) < 1e-9 && std::fabs(limiter_.v()) < 1e-6) {
    limiter_.reset(0);
    state_ = State::inactive;
  }
  return {};
}

ErrorId Controller::clamp_to(double lo_mm, double hi_mm) noexcept {
  const double p = limiter_.pos();
  if (p >= lo_mm && p <= hi_mm) return {};
  limiter_.hold_at(std::clamp(p, lo_mm, hi_mm));
  return fail(ErrorId::DistCtrlSwLimit);
}

void Controller::stop(bool clear) noexcept {
  if (state_ != State::error) state_ = State::inactive;
  limiter_.hold_at(limiter_.pos());
  if (!clear) return;
  s_ = base_;
  set_pos_mm_ = kKeep;
  set_dist_mm_ = 0;
  configure_chain();
}

}  // namespace nck::distctrl
