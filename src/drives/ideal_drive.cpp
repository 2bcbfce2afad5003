#include "nck/drives/ideal_drive.hpp"

namespace nck::drives {

const DriveFeedback& IdealDrive::step(const DriveCommand& cmd, bool fault) noexcept {
  const std::uint16_t bits = device_.step(cmd.controlword, fault);
  const bool enabled = device_.state() == cia402::State::operation_enabled;
  fb_.statusword = static_cast<std::uint16_t>(bits | (enabled ? cia402::sw::target_reached : 0));
  fb_.mode_display = enabled ? cmd.mode_of_operation : std::int8_t{0};
  fb_.fault = device_.state() == cia402::State::fault;
  if (enabled) {
    fb_.actual_vel = cmd.target_vel;
    fb_.actual_pos = cmd.target_pos;
  } else {
    fb_.actual_vel = 0;
  }
  fb_.following_error = enabled ? 0.0 : cmd.target_pos - fb_.actual_pos;
  return fb_;
}

}  // namespace nck::drives
