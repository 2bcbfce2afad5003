#pragma once
// One axis's or spindle's drive interface as it crosses the cyclic
// boundary: what the NC writes to the drive and what the drive reports,
// as plain, trivially copyable data (a HAL component copies it to pins,
// an EtherCAT master to its process image, the simulated machine to its
// simulated drive).
//
// Indexed by the machine's axis list (config::Machine::axes, achs_mds
// order): path axes and spindles alike. Only a drive whose kenngr.antr_typ
// is 8 (CANopen / CiA 402) and that P-AXIS-00790 does not switch to
// simulation uses the CiA 402 words; a conventional drive (antr_typ 1)
// takes target_vel, whose position loop the NC closes with kv (and reports
// actual_pos); a simulated or virtual drive none of it.
//
// Units: positions in mm (deg for rotary axes and spindles), velocities in
// mm/s (deg/s). The drive's own scaling (increments) is the integrator's.
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace nck::drives {

// At most this many axis lists have a drive slot (the machine's
// axes beyond it have none; config refuses more CiA 402 drives).
inline constexpr std::size_t kMaxDrives = 64;

// How the NC talks to a drive (kenngr.antr_typ, P-AXIS-00020, after
// P-AXIS-00790's switch to simulation).
enum class DriveKind : std::uint8_t {
  simulation,    // 4, or any with P-AXIS-00790 = 1: the NC simulates it
  virtual_,      // 16: no drive at all
  conventional,  // 1: velocity set point; the NC closes the position loop
  cia402,        // 8: CANopen / EtherCAT drive profile
};

// NC -> drive, written by every tick.
struct DriveCommand {
  std::uint16_t controlword = 0;        // 0x6040 (CiA 402 only)
  std::int8_t mode_of_operation = 0;    // 0x6060: 8 = CSP, 9 = CSV, 6 = homing (CiA 402 only)
  bool enable = false;                  // the NC wants the drive powered (all kinds but virtual)
  double target_pos = 0;                // 0x607A: set point, mm / deg
  double target_vel = 0;                // 0x60FF: set-point velocity, mm/s / deg/s
};

// Drive -> NC, read by every tick (what the drive reported last).
struct DriveFeedback {
  std::uint16_t statusword = 0;         // 0x6041 (CiA 402 only)
  std::int8_t mode_display = 0;         // 0x6061: the mode the drive runs
  bool fault = false;                   // amplifier fault (conventional drives; CiA 402: statusword bit 3)
  double actual_pos = 0;                // 0x6064, mm / deg
  double actual_vel = 0;                // 0x606C, mm/s / deg/s
  double following_error = 0;           // 0x60F4, mm / deg
};

static_assert(std::is_trivially_copyable_v<DriveCommand> && std::is_standard_layout_v<DriveCommand>);
static_assert(std::is_trivially_copyable_v<DriveFeedback> && std::is_standard_layout_v<DriveFeedback>);

}  // namespace nck::drives
