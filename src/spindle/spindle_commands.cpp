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
                                                       const config::ChannelSpindle& sp,
                                                       const config::SimConfig& sim, double cycle_s) {
  if (!(cycle_s > 0) || !std::isfinite(cycle_s))
    return std::unexpected(make_diagnostic(ErrorId::SpindleNotConfigured,
                                           SourceLoc{sp.source.file, sp.source.line, 0},
                                           fmt::format("spindle {}: cycle time {} s is not positive",
                                                       sp.name, cycle_s)));
  *this = SpindleAxis{};
  p_ = SpindleParams::from(axis, sp, sim, cycle_s);
  gear_ = p_.initial_gear;
  pos_deg_ = wrap_modulo(0, gear().modulou, gear().moduloo);
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
  // 60254 is the one error that changes the spindle's state (FCT-S1 2.3).
  error_ = id;
  mode_ = SpindleMode::error;
  update_status();
  return err(id);
}

void SpindleAxis::adopt_pending_tool() noexcept {
  // Tool limits take effect on the way from standstill into motion (2.8.5).
  if (tool_has_pending_ && v_deg_s_ == 0) {
    tool_ = tool_pending_;
    tool_has_pending_ = false;
  }
}

SpindleResult SpindleAxis::rotate(double rpm, bool g167) noexcept {
  if (auto g = guard(); !g.ok()) return g;
  if (!std::isfinite(rpm)) return err(ErrorId::SpindleBadValue);
  const int dir = sign_of(rpm);
  if (dir != 0 && !check_preferred_direction_ok(dir)) return fail(ErrorId::SpindlePreferredDirection);
  adopt_pending_tool();
  programmed_rpm_ = rpm;
  ignore_override_ = g167;  // a new speed ends a former G167 (2.4.1)
  mode_ = SpindleMode::rotate;
  planned_ = pos_done_ = false;
  SpindleResult r;
  if (std::fabs(rpm_to_deg_s(rpm)) > max_speed_deg_s()) r = SpindleResult{ErrorId::SpindleSpeedLimited, true};
  update_status();
  return r;
}

SpindleResult SpindleAxis::stop() noexcept {
  if (auto g = guard(); !g.ok()) return g;
  planned_ = pos_done_ = false;
  // After the control limit the reference is lost: M5 homes on the way down.
  if (ref_lost_ && p_.can_position && !p_.open_loop && v_deg_s_ != 0) {
    begin_homing(After::stop, Direction::none);
  } else {
    mode_ = SpindleMode::stop;
  }
  update_status();
  return {};
}

SpindleResult SpindleAxis::position(double target_deg, Direction dir, double rpm, bool g167) noexcept {
  if (auto g = guard(); !g.ok()) return g;
  if (!p_.can_position) return err(ErrorId::SpindleSensorlessPositioning);
  if (!std::isfinite(target_deg) || !std::isfinite(rpm) || rpm == 0) return err(ErrorId::SpindleBadValue);
  if (dir != Direction::none && !check_preferred_direction_ok(static_cast<int>(dir)))
    return fail(ErrorId::SpindlePreferredDirection);
  if (dir == Direction::none && v_deg_s_ == 0 && preferred() != 0)
    dir = static_cast<Direction>(preferred());  // shortest path may not break the preference
  adopt_pending_tool();
  ignore_override_ = g167;
  const double speed = std::fabs(rpm_to_deg_s(rpm));
  if (!homed_) {
    home_target_deg_ = target_deg;
    home_target_dir_ = dir;
    home_target_speed_ = speed;
    home_target_overridable_ = true;
    begin_homing(After::target, dir);
  } else {
    begin_positioning(SpindleMode::position, target_deg, dir, speed, true);
  }
  update_status();
  return {};
}

SpindleResult SpindleAxis::home() noexcept {
  if (auto g = guard(); !g.ok()) return g;
  if (!p_.can_position) return err(ErrorId::SpindleSensorlessPositioning);
  adopt_pending_tool();
  begin_homing(After::refpkt, Direction::none);
  update_status();
  return {};
}

void SpindleAxis::begin_homing(After after, Direction dir) noexcept {
  mode_ = SpindleMode::homing;
  after_home_ = after;
  mark_found_ = false;
  planned_ = pos_done_ = false;
  int d = static_cast<int>(dir);
  if (d == 0) d = sign_of(v_deg_s_);
  if (d == 0) d = preferred();
  home_dir_ = d == 0 ? 1 : d;
}

void SpindleAxis::begin_positioning(SpindleMode mode, double target_deg, Direction dir,
                                    double speed_deg_s, bool overridable) noexcept {
  mode_ = mode;
  target_deg_ = wrap_modulo(target_deg, gear().modulou, gear().moduloo);
  pos_dir_req_ = dir;
  pos_speed_deg_s_ = speed_deg_s;
  pos_overridable_ = overridable;
  planned_ = false;
  pos_done_ = false;
  remaining_deg_ = 0;
}

SpindleResult SpindleAxis::start_gear_change(std::uint32_t stage) noexcept {
  if (auto g = guard(); !g.ok()) return g;
  if (stage < 1 || stage > config::kMaxGearStages) return err(ErrorId::SpindleGearStageInvalid);
  gc_stage_ = stage;
  if (!p_.can_position) {
    // Nothing to position: the spindle just stops, then the PLC shifts.
    mode_ = SpindleMode::gear_change;
    planned_ = true;
    pos_done_ = false;
    remaining_deg_ = 0;
    pos_dir_ = 0;
  } else {
    Direction dir = static_cast<Direction>(preferred());
    begin_positioning(SpindleMode::gear_change, gear().getr_schalt_pos, dir, gear().vb_eilgang, false);
  }
  update_status();
  return {};
}

SpindleResult SpindleAxis::finish_gear_change() noexcept {
  if (!configured_) return err(ErrorId::SpindleNotConfigured);
  if (mode_ != SpindleMode::gear_change || !status_.gear_change_ready)
    return err(ErrorId::SpindleGearChangeState);
  gear_ = gc_stage_;
  pos_deg_ = wrap_modulo(pos_deg_, gear().modulou, gear().moduloo);
  mode_ = SpindleMode::stop;
  planned_ = pos_done_ = false;
  update_status();
  return {};
}

SpindleResult SpindleAxis::load_gear_data(std::uint32_t stage) noexcept {
  if (auto g = guard(); !g.ok()) return g;
  if (stage < 1 || stage > config::kMaxGearStages) return err(ErrorId::SpindleGearStageInvalid);
  if (v_deg_s_ != 0) return err(ErrorId::SpindleNotAtStandstill);
  gear_ = stage;
  pos_deg_ = wrap_modulo(pos_deg_, gear().modulou, gear().moduloo);
  update_status();
  return {};
}

}  // namespace nck::spindle
