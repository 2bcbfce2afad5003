#pragma once
// What crosses between a spindle's interpolator and its drive each cycle:
// the command the NC sends and the actual values the drive measures. Both
// on the drive's side of the sign flip of getriebe[i].reverse (P-AXIS-00159):
// the NC flips its command on the way out and the measured values on the
// way in, so a reversed drive needs nothing special.
//
// The drive itself is not here: a simulated one lives in nck/sim
// (sim::SpindleDrive), a real one behind the integrator's I/O. The values
// reach the kernel through TickInput (kernel::TickInput::spindle_measured)
// or, for a drive that answers within the cycle, kernel::SpindleDrives.
#include <cstdint>

namespace nck::spindle {

// The set point of one cycle as the drive gets it.
struct DriveCommand {
  double step_deg = 0;            // the set point's increment in this cycle
  double pos_deg = 0;             // the set-point position after it
  double feedforward_weight = 0;  // G135 with G136's weight, 0 = off (G137)
  std::uint32_t gear_stage = 1;   // the drive's data (kv) follow the gear stage
};

// The drive's actual values at the end of a cycle. Speed in deg/s, the
// internal unit: the kernel judges "speed reached" and standstill from it
// without a round trip through rpm.
struct DriveFeedback {
  double actual_speed_deg_s = 0;
  double actual_pos_deg = 0;  // need not be wrapped: the NC wraps it
  bool valid = false;         // false: nothing measured; the NC takes its own set point
  // The encoder resets its count at the next index pulse (HAL's
  // index-enable, asked for when G33 waits for the zero mark): until then
  // its angle is no zero-mark reference.
  bool index_reset_pending = false;
};

}  // namespace nck::spindle
