// Commands of the spindle interpolator: each checks, then changes the mode;
// the motion itself happens in tick().
#include <cmath>
#include <fmt/format.h>

#include "nck/spindle/spindle_axis.hpp"

namespace nck::spindle {
namespace {

SpindleResult err(ErrorId id) { return SpindleResult{id, false}; }
int sign_of(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

}  // namespace

std::string_view mode_name(SpindleMode m) noexcept {
  switch (m) {
    case SpindleMode::stop: return "stop";
    case SpindleMode::rotate: return "rotate";
    case SpindleMode::position: return "position";
    case SpindleMode::homing: return "homing";
    case SpindleMode::gear_change: return "gear_change";
    case SpindleMode::axis: return "axis";
    case SpindleMode::error: return "error";
  }
  return "stop";
}

std::expected<void, Diagnostic> SpindleAxis::configure(const config::AxisConfig* axis,
                                                       const config::ChannelSpindle& sp, double cycle_s) {
  if (!(cycle_s > 0) || !std::isfinite(cycle_s))
    return std::unexpected(make_diagnostic(ErrorId::SpindleNotConfigured,
                                           SourceLoc{sp.source.file, sp.source.line, 0},
                                           fmt::format("spindle {}: cycle time {} s is not positive",
                                                       sp.name, cycle_s)));
  *this = SpindleAxis{};
  cfg_ = SpindleConfig::from(axis, sp, cycle_s);
  gear_ = cfg_.initial_gear;
  set_.pos_deg = gear().wrap(0);
  configured_ = true;
  update_status();
  return {};
}

SpindleResult SpindleAxis::guard() const noexcept {
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (mode_ == SpindleMode::error) return err(ErrorId::SpindleInErrorState);
  if (mode_ == SpindleMode::axis) return err(ErrorId::SpindleAxisMode);
  return {};
}

SpindleResult SpindleAxis::fail(ErrorId id) noexcept {
  const Changed changed(*this);
  // 60254 is the one error that changes the spindle's state (FCT-S1 2.3).
  error_ = id;
  mode_ = SpindleMode::error;
  update_status();
  return err(id);
}

void SpindleAxis::adopt_pending_tool() noexcept {
  // Tool limits take effect on the way from standstill into motion (2.8.5).
  if (tool_.has_pending && set_.vel_deg_s == 0) {
    tool_.active = tool_.pending;
    tool_.has_pending = false;
  }
}

SpindleResult SpindleAxis::rotate(double rpm, bool g167) noexcept {
  const Changed changed(*this);
  if (auto g = guard(); !g.ok()) return g;
  if (!std::isfinite(rpm)) return err(ErrorId::SpindleBadValue);
  if (!direction_allowed(cfg_.preferred_direction, static_cast<Direction>(sign_of(rpm))))
    return fail(ErrorId::SpindlePreferredDirection);
  adopt_pending_tool();
  speed_.programmed_rpm = rpm;
  speed_.ignore_override = g167;  // a new speed ends a former G167 (2.4.1)
  mode_ = SpindleMode::rotate;
  pos_.planned = pos_.done = false;
  SpindleResult r;
  if (std::fabs(rpm_to_deg_s(rpm)) > max_speed_deg_s()) r = SpindleResult{ErrorId::SpindleSpeedLimited, true};
  update_status();
  return r;
}

SpindleResult SpindleAxis::stop() noexcept {
  const Changed changed(*this);
  if (auto g = guard(); !g.ok()) return g;
  pos_.planned = pos_.done = false;
  // After the control limit the reference is lost: M5 homes on the way down.
  if (ref_.lost && cfg_.auto_homing && cfg_.can_position && !cfg_.open_loop && set_.vel_deg_s != 0) {
    begin_homing(AfterHoming::stop, Direction::none);
  } else {
    mode_ = SpindleMode::stop;
  }
  update_status();
  return {};
}

SpindleResult SpindleAxis::position(double target_deg, Direction dir, double rpm, bool g167) noexcept {
  const Changed changed(*this);
  if (auto g = guard(); !g.ok()) return g;
  if (!cfg_.can_position) return err(ErrorId::SpindleSensorlessPositioning);
  if (!std::isfinite(target_deg) || !std::isfinite(rpm) || rpm == 0) return err(ErrorId::SpindleBadValue);
  if (!direction_allowed(cfg_.preferred_direction, dir)) return fail(ErrorId::SpindlePreferredDirection);
  if (dir == Direction::none && set_.vel_deg_s == 0)
    dir = cfg_.preferred_direction;  // shortest path may not break the preference
  adopt_pending_tool();
  speed_.ignore_override = g167;
  const double speed = std::fabs(rpm_to_deg_s(rpm));
  if (!ref_.homed && cfg_.auto_homing) {
    // From standstill M19 takes the shorter way (FCT-S1 2.3.2); the homing
    // that comes first must not lose it, so it turns that way already and the
    // positioning after the zero mark goes on in the same direction.
    if (dir == Direction::none && set_.vel_deg_s == 0) dir = shorter_way(target_deg);
    homing_.target_deg = target_deg;
    homing_.target_dir = dir;
    homing_.target_speed_deg_s = speed;
    homing_.target_overridable = true;
    begin_homing(AfterHoming::go_to_target, dir);
  } else {
    begin_positioning(SpindleMode::position, target_deg, dir, speed, true);
  }
  update_status();
  return {};
}

Direction SpindleAxis::shorter_way(double target_deg) const noexcept {
  const double travel = m19_travel_deg(set_.pos_deg, target_deg, Direction::none, 0, gear().modulo_low_deg,
                                       gear().modulo_high_deg);
  return travel < 0 ? Direction::negative : Direction::positive;
}

SpindleResult SpindleAxis::home() noexcept {
  const Changed changed(*this);
  if (auto g = guard(); !g.ok()) return g;
  if (!cfg_.can_position) return err(ErrorId::SpindleSensorlessPositioning);
  adopt_pending_tool();
  begin_homing(AfterHoming::go_to_reference, Direction::none);
  update_status();
  return {};
}

void SpindleAxis::begin_homing(AfterHoming after, Direction dir) noexcept {
  mode_ = SpindleMode::homing;
  homing_.after = after;
  homing_.mark_found = false;
  pos_.planned = pos_.done = false;
  int d = static_cast<int>(dir);
  if (d == 0) d = sign_of(set_.vel_deg_s);
  if (d == 0) d = static_cast<int>(cfg_.preferred_direction);
  homing_.dir = d == 0 ? 1 : d;
}

void SpindleAxis::begin_positioning(SpindleMode mode, double target_deg, Direction dir,
                                    double speed_deg_s, bool overridable) noexcept {
  mode_ = mode;
  pos_.target_deg = gear().wrap(target_deg);
  pos_.requested_dir = dir;
  pos_.speed_deg_s = speed_deg_s;
  pos_.overridable = overridable;
  pos_.planned = false;
  pos_.done = false;
  pos_.remaining_deg = 0;
}

SpindleResult SpindleAxis::start_gear_change(std::uint32_t stage) noexcept {
  const Changed changed(*this);
  if (auto g = guard(); !g.ok()) return g;
  if (stage < 1 || stage > config::kMaxGearStages) return err(ErrorId::SpindleGearStageInvalid);
  pos_.gear_change_stage = stage;
  if (!cfg_.can_position) {
    // Nothing to position: the spindle just stops, then the PLC shifts.
    mode_ = SpindleMode::gear_change;
    pos_.planned = true;
    pos_.done = false;
    pos_.remaining_deg = 0;
    pos_.dir = 0;
  } else {
    begin_positioning(SpindleMode::gear_change, gear().gear_change_pos_deg, cfg_.preferred_direction,
                      gear().rapid_speed_deg_s, false);
  }
  update_status();
  return {};
}

SpindleResult SpindleAxis::finish_gear_change() noexcept {
  const Changed changed(*this);
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (mode_ != SpindleMode::gear_change || !status_.gear_change_ready)
    return err(ErrorId::SpindleGearChangeState);
  gear_ = pos_.gear_change_stage;
  set_.pos_deg = gear().wrap(set_.pos_deg);
  mode_ = SpindleMode::stop;
  pos_.planned = pos_.done = false;
  update_status();
  return {};
}

SpindleResult SpindleAxis::load_gear_data(std::uint32_t stage) noexcept {
  const Changed changed(*this);
  if (auto g = guard(); !g.ok()) return g;
  if (stage < 1 || stage > config::kMaxGearStages) return err(ErrorId::SpindleGearStageInvalid);
  if (set_.vel_deg_s != 0) return err(ErrorId::SpindleNotAtStandstill);
  gear_ = stage;
  set_.pos_deg = gear().wrap(set_.pos_deg);
  update_status();
  return {};
}

}  // namespace nck::spindle
