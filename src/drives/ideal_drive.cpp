#include "nck/drives/ideal_drive.hpp"

namespace nck::drives {

namespace cia = cia402;

const DriveFeedback& IdealDrive::step(const DriveCommand& cmd, bool fault, double cycle_s) noexcept {
  const std::uint16_t bits = device_.step(cmd.controlword, fault);
  const bool enabled = device_.state() == cia::State::operation_enabled;
  const auto mode = static_cast<cia::Mode>(cmd.mode_of_operation);
  std::uint16_t mode_bits = enabled ? cia::sw::target_reached : 0;
  fb_.actual_vel = 0;
  if (enabled && mode == cia::Mode::homing) {
    mode_bits = home(cmd);
  } else if (enabled && mode == cia::Mode::cyclic_sync_velocity) {
    fb_.actual_vel = cmd.target_vel;
    fb_.actual_pos += cmd.target_vel * cycle_s;
  } else if (enabled) {
    fb_.actual_vel = cmd.target_vel;
    fb_.actual_pos = cmd.target_pos;
  }
  if (!enabled || mode != cia::Mode::homing) homing_left_ = 0;  // a search ends with its mode
  last_controlword_ = cmd.controlword;
  fb_.statusword = static_cast<std::uint16_t>(bits | mode_bits);
  fb_.mode_display = enabled ? cmd.mode_of_operation : std::int8_t{0};
  fb_.fault = device_.state() == cia::State::fault;
  fb_.following_error = enabled && mode != cia::Mode::homing ? 0.0 : cmd.target_pos - fb_.actual_pos;
  return fb_;
}

const DriveFeedback& IdealDrive::follow_velocity(const DriveCommand& cmd, double cycle_s) noexcept {
  fb_.actual_vel = cmd.enable ? cmd.target_vel : 0.0;
  fb_.actual_pos += fb_.actual_vel * cycle_s;
  fb_.following_error = cmd.target_pos - fb_.actual_pos;
  return fb_;
}

std::uint16_t IdealDrive::home(const DriveCommand& cmd) noexcept {
  const bool start = (cmd.controlword & cia::cw::homing_start_bit) && !(last_controlword_ & cia::cw::homing_start_bit);
  if (start) {
    homing_left_ = kHomingCycles;
    homed_ = false;
  } else if (homing_left_ > 0 && --homing_left_ == 0) {
    fb_.actual_pos = 0;  // the home offset
    homed_ = true;
  }
  if (homing_left_ > 0) return 0;  // searching: neither attained nor target reached
  return homed_ ? static_cast<std::uint16_t>(cia::sw::target_reached | cia::sw::homing_attained)
                : cia::sw::target_reached;
}

}  // namespace nck::drives
