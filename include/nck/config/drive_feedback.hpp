#pragma once
// What an axis's drive reports back, from its machine data alone. The
// spindle refuses what needs a position it does not know (70252), and
// `nck check` warns of it before a program asks (config checks).
#include "nck/config/machine.hpp"

namespace nck::config {

// A position-controlled drive, or a speed-controlled one with position
// feedback (antr.operation_mode OPEN_POSITION_LOOP_POS_FEEDBACK, P-AXIS-00320).
// Without it a spindle cannot position (M19), home (G74) or approach its
// gear-change position: the seed's sensorless spindle (FCT-S1 2.2.4).
inline bool knows_position(const AxisConfig& axis) noexcept {
  return !axis.is_speed_controlled() || axis.drive_mode == DriveMode::open_loop_pos_feedback;
}

}  // namespace nck::config
