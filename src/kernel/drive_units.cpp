#include "drive_units.hpp"

#include <cmath>

namespace nck::kernel {

namespace cia = drives::cia402;

void DriveUnits::configure(const config::Machine& m, double cycle_s) {
  slots_.clear();
  for (std::size_t i = 0; i < m.axes.size() && i < drives::kMaxDrives; ++i) {
    const config::AxisConfig& ax = m.axes[i];
    if (!ax.is_cia402()) continue;
    Slot s;
    s.axis = static_cast<std::uint8_t>(i);
    // A speed-controlled spindle runs in cyclic synchronous velocity,
    // everything else (path axes, position-controlled spindles) in
    // cyclic synchronous position.
    s.mode = ax.is_spindle() && ax.is_speed_controlled() ? cia::Mode::cyclic_sync_velocity
                                                          : cia::Mode::cyclic_sync_position;
    s.timeout_cycles = static_cast<std::uint32_t>(std::ceil(ax.drive_enable_timeout_s / cycle_s));
    slots_.push_back(s);
  }
}

DriveReport DriveUnits::step(const TickInput& in, TickOutput& out, bool enabled) noexcept {
  DriveReport r;
  for (Slot& s : slots_) {
    const drives::DriveFeedback& fb = in.drives[s.axis];
    const cia::State now = cia::decode(fb.statusword);
    drives::DriveCommand& cmd = out.drives[s.axis];
    // A drive that faulted stays there until the operator resets: the
    // goal asks for power only while nothing is reported.
    const cia::Goal goal = s.reported || !enabled ? cia::Goal::disabled : cia::Goal::enabled;
    cmd.controlword = s.master.controlword(now, goal);
    cmd.mode_of_operation = static_cast<std::int8_t>(s.mode);
    cmd.enable = goal == cia::Goal::enabled;
    const bool in_operation = now == cia::State::operation_enabled;
    if (!in_operation) r.ready = false;
    if (!enabled) s.reached = false;  // switched off on purpose: its enable starts anew
    if (s.reported || !enabled) continue;
    ErrorId id{};
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

void DriveUnits::write_set_point(std::size_t axis_index, double pos, double vel, TickOutput& out) const noexcept {
  if (axis_index >= drives::kMaxDrives) return;
  out.drives[axis_index].target_pos = pos;
  out.drives[axis_index].target_vel = vel;
}

void DriveUnits::on_reset() noexcept {
  for (Slot& s : slots_) {
    s.reported = false;
    s.reached = false;
  }
}

}  // namespace nck::kernel
