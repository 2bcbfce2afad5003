#include "drive_units.hpp"

#include <cmath>

namespace nck::kernel {

namespace cia = drives::cia402;

void DriveUnits::configure(const config::Machine& m, double cycle_s) {
  slots_.clear();
  slot_index_.fill(-1);
  cycle_s_ = cycle_s;
  for (std::size_t i = 0; i < m.axes.size() && i < drives::kMaxDrives; ++i) {
    const config::AxisConfig& ax = m.axes[i];
    if (!ax.is_cia402() && !ax.is_conventional()) continue;
    Slot s;
    s.axis = static_cast<std::uint8_t>(i);
    s.conventional = ax.is_conventional();
    s.kv_1_s = ax.gear(ax.initial_gear_stage).position_gain_1_s;
    // A speed-controlled spindle starts in cyclic synchronous velocity,
    // everything else (path axes, position-controlled spindles) in
    // cyclic synchronous position; a spindle's mode follows it (write_spindle).
    s.mode = ax.is_spindle() && ax.is_speed_controlled() ? cia::Mode::cyclic_sync_velocity
                                                          : cia::Mode::cyclic_sync_position;
    s.timeout_cycles = static_cast<std::uint32_t>(std::ceil(ax.drive_enable_timeout_s / cycle_s));
    s.homing_timeout_cycles = static_cast<std::uint32_t>(std::ceil(ax.drive_homing_timeout_s / cycle_s));
    slot_index_[i] = static_cast<std::int8_t>(slots_.size());
    slots_.push_back(s);
  }
}

DriveUnits::Slot* DriveUnits::slot_of(std::size_t axis_index) noexcept {
  return axis_index < drives::kMaxDrives && slot_index_[axis_index] >= 0
             ? &slots_[static_cast<std::size_t>(slot_index_[axis_index])]
             : nullptr;
}

const DriveUnits::Slot* DriveUnits::slot_of(std::size_t axis_index) const noexcept {
  return const_cast<DriveUnits*>(this)->slot_of(axis_index);
}

DriveReport DriveUnits::step(const TickInput& in, TickOutput& out, bool enabled) noexcept {
  DriveReport r;
  for (Slot& s : slots_) {
    if (s.conventional) {  // no state machine: powered while the machine lets it
      out.drives[s.axis].enable = enabled;
      continue;
    }
    const drives::DriveFeedback& fb = in.drives[s.axis];
    const cia::State now = cia::decode(fb.statusword);
    drives::DriveCommand& cmd = out.drives[s.axis];
    if (fb.mode_display != s.mode_shown) {
      s.mode_shown = fb.mode_display;
      out.emit(Event{{out.t_s, 0, {}}, drives::DriveEvent{static_cast<std::int8_t>(s.axis), fb.mode_display}});
    }
    // A drive that faulted stays there until the operator resets: the
    // goal asks for power only while nothing is reported.
    const cia::Goal goal = s.reported || !enabled ? cia::Goal::disabled : cia::Goal::enabled;
    cmd.controlword = s.master.controlword(now, goal);
    cmd.mode_of_operation = static_cast<std::int8_t>(s.mode);
    cmd.enable = goal == cia::Goal::enabled;
    const bool in_operation = now == cia::State::operation_enabled;
    if (!in_operation) r.ready = false;
    if (!enabled) s.reached = false;  // switched off on purpose: its enable starts anew
    ErrorId id = step_homing(s, fb, in_operation && !s.reported && enabled);
    if (s.homing_attained) r.homed |= std::uint64_t{1} << s.axis;
    if (s.reported || !enabled) continue;
    if (s.reached && (now == cia::State::fault || now == cia::State::fault_reaction_active))
      id = ErrorId::KernelDriveFault;
    else if (s.reached && !in_operation)
      id = ErrorId::KernelDriveLostEnable;
    else if (!s.reached && s.master.waiting_cycles() > s.timeout_cycles)
      id = ErrorId::KernelDriveEnableTimeout;
    if (in_operation) s.reached = true;
    if (id != ErrorId{} && r.axis < 0) {
      r.error = id;
      r.axis = static_cast<std::int8_t>(s.axis);
    }
    if (id != ErrorId{}) s.reported = true;
  }
  return r;
}

// Drive-controlled homing's cycle: what the drive reported of the homing
// the spindle asked for last cycle; an error's ID, or none.
ErrorId DriveUnits::step_homing(Slot& s, const drives::DriveFeedback& fb, bool in_operation) noexcept {
  const auto outcome = s.homing.step(s.wants_homing && in_operation, fb.statusword, fb.mode_display);
  s.homing_attained = outcome == cia::DriveHoming::Outcome::attained;
  if (s.homing_attained) s.target_pos = fb.actual_pos;  // the drive's new reference
  if (outcome == cia::DriveHoming::Outcome::failed) return ErrorId::KernelDriveHomingError;
  if (s.homing.cycles() > s.homing_timeout_cycles) return ErrorId::KernelDriveHomingTimeout;
  return ErrorId{};
}

bool DriveUnits::command_homing(Slot& s, bool wants_homing, cia::Mode follow, drives::DriveCommand& cmd) noexcept {
  s.wants_homing = wants_homing;
  s.mode = s.homing.active() ? cia::Mode::homing : follow;
  cmd.mode_of_operation = static_cast<std::int8_t>(s.mode);
  cmd.controlword = static_cast<std::uint16_t>(cmd.controlword | s.homing.start_bit());
  return s.homing.active();
}

void DriveUnits::write_set_point(std::size_t axis_index, double pos, bool wants_homing, const TickInput& in,
                                 TickOutput& out) noexcept {
  Slot* s = slot_of(axis_index);
  if (s == nullptr) return;
  drives::DriveCommand& cmd = out.drives[axis_index];
  if (!s->conventional && command_homing(*s, wants_homing, cia::Mode::cyclic_sync_position, cmd)) {
    s->target_pos = cmd.target_pos = in.drives[axis_index].actual_pos;  // the drive moves on its own
    cmd.target_vel = 0;
    return;
  }
  double vel = (pos - s->target_pos) / cycle_s_;
  if (s->conventional) {
    // The drive's actual position answers the last set point (it was
    // written a cycle ago): its following error is measured against that.
    const double following_error = s->target_pos - in.drives[axis_index].actual_pos;
    vel += s->kv_1_s * following_error;
    if (!cmd.enable) vel = 0;  // not powered: no loop to close
  }
  s->target_pos = pos;
  cmd.target_pos = pos;
  cmd.target_vel = vel;
}

void DriveUnits::write_spindle_velocity(std::size_t axis_index, double pos_deg, double vel_deg_s, TickOutput& out) noexcept {
  Slot* s = slot_of(axis_index);
  if (s == nullptr) return;
  drives::DriveCommand& cmd = out.drives[axis_index];
  s->target_pos = pos_deg;
  cmd.target_pos = pos_deg;
  cmd.target_vel = cmd.enable ? vel_deg_s : 0.0;  // not powered: no loop to close
}

void DriveUnits::write_spindle(std::size_t axis_index, const SpindleCycle& c, const TickInput& in,
                               TickOutput& out) noexcept {
  Slot* s = slot_of(axis_index);
  if (s == nullptr) return;
  const drives::DriveFeedback& fb = in.drives[axis_index];
  drives::DriveCommand& cmd = out.drives[axis_index];
  command_homing(*s, c.wants_homing, c.mode, cmd);
  // Not following the NC (off, or homing on its own): the set point stays
  // where the drive is, so that enabling or the next mode starts there.
  if (cia::decode(fb.statusword) != cia::State::operation_enabled || s->homing.active())
    s->target_pos = fb.actual_pos;
  else
    s->target_pos += c.step_deg;
  cmd.target_pos = s->target_pos;
  cmd.target_vel = s->homing.active() ? 0.0 : c.step_deg / cycle_s_;
}

bool DriveUnits::homing_attained(std::size_t axis_index) const noexcept {
  const Slot* s = slot_of(axis_index);
  return s != nullptr && s->homing_attained;
}

double DriveUnits::lag(std::size_t axis_index, const TickInput& in) const noexcept {
  const Slot* s = slot_of(axis_index);
  return s != nullptr ? s->target_pos - in.drives[axis_index].actual_pos : 0.0;
}

void DriveUnits::on_reset() noexcept {
  for (Slot& s : slots_) {
    s.reported = false;
    s.reached = false;
  }
}

}  // namespace nck::kernel
