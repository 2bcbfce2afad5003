#pragma once
// A CiA 402 drive reports another mode of operation (0x6061): power-up
// (0 -> 8 / 9), a spindle between velocity and position control (M3,
// M19), drive-controlled homing (6), or 0 when its operation ends. The
// machine's event (channel 0); `axis` is the machine axis list index
// (Kernel::axis_name). Its JSON writer is beside it (docs/outputs.md).
#include <cstdint>

#include "nck/core/event_head.hpp"
#include "nck/drives/cia402.hpp"

namespace nck::drives {

struct DriveEvent {
  std::int8_t axis = 0;
  std::int8_t mode = 0;  // 0x6061 as the drive reports it
};

// "csp", "csv", "homing" ... for a mode number; "none" for 0, "other" beyond nck's.
constexpr const char* mode_short_name(std::int8_t mode) noexcept {
  switch (static_cast<cia402::Mode>(mode)) {
    case cia402::Mode::none: return "none";
    case cia402::Mode::profile_position: return "pp";
    case cia402::Mode::profile_velocity: return "pv";
    case cia402::Mode::homing: return "homing";
    case cia402::Mode::cyclic_sync_position: return "csp";
    case cia402::Mode::cyclic_sync_velocity: return "csv";
    case cia402::Mode::cyclic_sync_torque: return "cst";
  }
  return "other";
}

template <class Json, class Names>
void write_json(Json& j, const DriveEvent& e, const EventHead&, const Names& names) {
  j["axis"] = names.axis(e.axis);
  j["mode"] = mode_short_name(e.mode);
  j["opmode"] = e.mode;
}

}  // namespace nck::drives
