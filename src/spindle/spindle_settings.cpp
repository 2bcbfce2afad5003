// Settings of the spindle interpolator that do not start a motion: override,
// weightings, feedforward, tool dynamics, feedhold, reset, axis mode.
#include <algorithm>
#include <cmath>

#include "nck/spindle/spindle_axis.hpp"

namespace nck::spindle {
namespace {
SpindleResult err(ErrorId id) { return SpindleResult{id, false}; }
}  // namespace

int SpindleAxis::preferred() const noexcept {
  if (!p_.vorz_richtung) return 0;
  return p_.beweg_richt_positive ? 1 : -1;
}

bool SpindleAxis::check_preferred_direction_ok(int dir) const noexcept {
  const int pref = preferred();
  return pref == 0 || dir == 0 || dir == pref;
}

void SpindleAxis::set_override_pct(double pct) noexcept {
  if (!std::isfinite(pct)) return;  // a broken HLI value keeps the last one
  override_pct_ = std::clamp(pct, 0.0, 200.0);
  update_status();
}

void SpindleAxis::suppress_override() noexcept {
  ignore_override_ = true;
  update_status();
}

SpindleResult SpindleAxis::set_accel_weight_pct(double pct) noexcept {
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (!std::isfinite(pct) || pct <= 0) return err(ErrorId::SpindleBadValue);
  accel_weight_ = pct / 100.0;  // capped by a_max where it is applied
  return {};
}

SpindleResult SpindleAxis::feedforward_on() noexcept {
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  ff_on_ = true;
  return {};
}

SpindleResult SpindleAxis::feedforward_weight_pct(double pct) noexcept {
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (!std::isfinite(pct) || pct < 0 || pct > 100) return err(ErrorId::SpindleBadValue);
  ff_weight_ = pct / 100.0;
  return {};
}

SpindleResult SpindleAxis::feedforward_off() noexcept {
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  ff_on_ = false;  // the weighting is kept for the next G135
  return {};
}

void SpindleAxis::set_tool_dynamics(const ToolDynamics& t) noexcept {
  auto clean = [](double v) { return std::isfinite(v) && v > 0 ? v : 0.0; };
  tool_pending_ = ToolDynamics{clean(t.vb_min_rpm), clean(t.vb_max_rpm), clean(t.a_max_deg_s2)};
  tool_has_pending_ = true;
}

SpindleResult SpindleAxis::adopt_tool_dynamics_now() noexcept {
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (tool_has_pending_) tool_ = tool_pending_;
  tool_has_pending_ = false;
  return {};
}

SpindleResult SpindleAxis::default_dynamic_data() noexcept {
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (v_deg_s_ != 0) return err(ErrorId::SpindleNotAtStandstill);
  tool_ = ToolDynamics{};
  tool_has_pending_ = false;
  return {};
}

void SpindleAxis::set_feedhold(bool on) noexcept {
  feedhold_ = on;
  update_status();
}

void SpindleAxis::reset() noexcept {
  if (!configured_) return;
  error_ = ErrorId{};
  const bool keep = p_.no_stop_by_channel_reset &&
                    (mode_ == SpindleMode::rotate || mode_ == SpindleMode::position);
  if (!keep) {
    mode_ = SpindleMode::stop;  // brakes in tick(); no automatic homing on reset
    planned_ = pos_done_ = false;
    after_home_ = After::none;
  }
  update_status();
}

SpindleResult SpindleAxis::enter_axis_mode() noexcept {
  if (auto g = guard(); !g.ok()) return g;
  if (v_deg_s_ != 0) return err(ErrorId::SpindleNotAtStandstill);
  mode_ = SpindleMode::axis;
  planned_ = pos_done_ = false;
  update_status();
  return {};
}

void SpindleAxis::axis_set_point(double pos_deg, double vel_deg_s) noexcept {
  if (mode_ != SpindleMode::axis || !std::isfinite(pos_deg) || !std::isfinite(vel_deg_s)) return;
  const double from = pos_deg_;
  pos_deg_ = wrap_modulo(pos_deg, gear().modulou, gear().moduloo);
  // The increment the path interpolator commanded, taken the short way round.
  const double r = range_deg();
  double d = wrap_modulo(pos_deg_ - from, -r / 2, r / 2);
  axis_step_deg_ += d;  // several set points in one cycle add up
  axis_vel_deg_s_ = vel_deg_s;
}

SpindleResult SpindleAxis::leave_axis_mode() noexcept {
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (mode_ != SpindleMode::axis) return {};
  mode_ = SpindleMode::stop;
  v_deg_s_ = 0;
  axis_step_deg_ = 0;
  axis_vel_deg_s_ = 0;
  update_status();
  return {};
}

}  // namespace nck::spindle
