// Settings of the spindle interpolator that do not start a motion: override,
// weightings, feedforward, tool dynamics, feedhold, reset, axis mode.
#include <algorithm>
#include <cmath>

#include "nck/spindle/spindle_axis.hpp"

namespace nck::spindle {
namespace {
SpindleResult err(ErrorId id) { return SpindleResult{id, false}; }
}  // namespace

void SpindleAxis::change_override_pct(double pct) noexcept {
  if (!std::isfinite(pct)) return;  // a broken HLI value keeps the last one
  const double clamped = std::clamp(pct, 0.0, 200.0);
  if (clamped == speed_.override_pct) return;
  const Changed changed(*this);
  speed_.override_pct = clamped;
  update_status();
}

void SpindleAxis::suppress_override() noexcept {
  const Changed changed(*this);
  speed_.ignore_override = true;
  update_status();
}

SpindleResult SpindleAxis::set_accel_weight_pct(double pct) noexcept {
  const Changed changed(*this);
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (!std::isfinite(pct) || pct <= 0) return err(ErrorId::SpindleBadValue);
  speed_.accel_weight = pct / 100.0;  // capped by a_max where it is applied
  return {};
}

SpindleResult SpindleAxis::feedforward_on() noexcept {
  const Changed changed(*this);
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  ff_.on = true;
  return {};
}

SpindleResult SpindleAxis::feedforward_weight_pct(double pct) noexcept {
  const Changed changed(*this);
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (!std::isfinite(pct) || pct < 0 || pct > 100) return err(ErrorId::SpindleBadValue);
  ff_.weight = pct / 100.0;
  return {};
}

SpindleResult SpindleAxis::feedforward_off() noexcept {
  const Changed changed(*this);
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  ff_.on = false;  // the weighting is kept for the next G135
  return {};
}

void SpindleAxis::set_tool_dynamics(const ToolDynamics& t) noexcept {
  const Changed changed(*this);
  auto clean = [](double v) { return std::isfinite(v) && v > 0 ? v : 0.0; };
  tool_.pending = ToolDynamics{clean(t.vb_min_rpm), clean(t.vb_max_rpm), clean(t.a_max_deg_s2)};
  tool_.has_pending = true;
}

SpindleResult SpindleAxis::adopt_tool_dynamics_now() noexcept {
  const Changed changed(*this);
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (tool_.has_pending) tool_.active = tool_.pending;
  tool_.has_pending = false;
  return {};
}

SpindleResult SpindleAxis::default_dynamic_data() noexcept {
  const Changed changed(*this);
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (set_.vel_deg_s != 0) return err(ErrorId::SpindleNotAtStandstill);
  tool_.active = ToolDynamics{};
  tool_.has_pending = false;
  return {};
}

void SpindleAxis::set_feedhold(bool on) noexcept {
  if (on == speed_.feedhold) return;  // the PLC writes it every cycle
  const Changed changed(*this);
  speed_.feedhold = on;
  update_status();
}

void SpindleAxis::reset() noexcept {
  const Changed changed(*this);
  if (!configured_) return;
  error_ = ErrorId{};
  const bool keep = cfg_.keep_running_on_reset &&
                    (mode_ == SpindleMode::rotate || mode_ == SpindleMode::position);
  if (!keep) {
    mode_ = SpindleMode::stop;  // brakes in tick(); no automatic homing on reset
    pos_.planned = pos_.done = false;
    homing_.after = AfterHoming::none;
  }
  update_status();
}

void SpindleAxis::abort() noexcept {
  const Changed changed(*this);
  if (!configured_) return;
  if (mode_ != SpindleMode::error) return reset();
  // The error state stays until a reset clears it (FCT-S1 2.3); the spindle
  // brakes to standstill in it, and nothing it was about to do follows.
  pos_.planned = pos_.done = false;
  homing_.after = AfterHoming::none;
  update_status();
}

void SpindleAxis::halt() noexcept {
  const Changed changed(*this);
  if (!configured_ || mode_ == SpindleMode::error || mode_ == SpindleMode::axis) return;
  mode_ = SpindleMode::stop;  // brakes in tick()
  pos_.planned = pos_.done = false;
  homing_.after = AfterHoming::none;
  update_status();
}

SpindleResult SpindleAxis::enter_axis_mode() noexcept {
  const Changed changed(*this);
  if (auto g = guard(); !g.ok()) return g;
  if (set_.vel_deg_s != 0) return err(ErrorId::SpindleNotAtStandstill);
  mode_ = SpindleMode::axis;
  pos_.planned = pos_.done = false;
  update_status();
  return {};
}

void SpindleAxis::axis_set_point(double pos_deg, double vel_deg_s) noexcept {
  const Changed changed(*this);
  if (mode_ != SpindleMode::axis || !std::isfinite(pos_deg) || !std::isfinite(vel_deg_s)) return;
  const double from = set_.pos_deg;
  set_.pos_deg = gear().wrap(pos_deg);
  // The increment the path interpolator commanded, taken the short way round.
  const double r = gear().range_deg();
  const double d = wrap_modulo(set_.pos_deg - from, -r / 2, r / 2);
  axis_.step_deg += d;  // several set points in one cycle add up
  axis_.vel_deg_s = vel_deg_s;
}

SpindleResult SpindleAxis::leave_axis_mode() noexcept {
  const Changed changed(*this);
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (mode_ != SpindleMode::axis) return {};
  mode_ = SpindleMode::stop;
  set_.vel_deg_s = 0;
  axis_ = AxisModeInput{};
  update_status();
  return {};
}

}  // namespace nck::spindle
