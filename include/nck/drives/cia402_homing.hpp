#pragma once
// Drive-controlled homing (CiA 402 homing mode, 6), the NC's side. With a
// digital drive the drive homes itself when G74 asks (FCT-S1 2.7): the NC
// selects homing mode, and once the drive reports that mode it starts the
// homing with a rising edge of controlword bit 4; the drive clears
// statusword bit 12 (homing attained) while it searches, and reports the
// end with bits 12 and 10 (target reached), or a failure with bit 13.
// A plain value stepped once per cycle, like Master: no allocation, no
// exception, no clock (the caller turns cycles() into a timeout).
#include <cstdint>

#include "nck/drives/cia402.hpp"

namespace nck::drives::cia402 {

class DriveHoming {
 public:
  enum class Outcome : std::uint8_t { none, attained, failed };

  // One cycle with the drive's last report. `wanted`: the NC wants the
  // drive homed (false ends a homing at any point: the mode goes back).
  // Returns attained or failed in the one cycle it happens.
  Outcome step(bool wanted, std::uint16_t statusword, std::int8_t mode_display) noexcept;
  // Homing mode is to be written (asked, not yet over).
  bool active() const noexcept { return phase_ == Phase::switching || phase_ == Phase::running; }
  // The controlword's homing start bit for this cycle.
  std::uint16_t start_bit() const noexcept { return phase_ == Phase::running ? cw::homing_start_bit : 0; }
  // Cycles since the homing was asked for (0 while idle or over).
  std::uint32_t cycles() const noexcept { return active() ? cycles_ : 0; }

 private:
  enum class Phase : std::uint8_t { idle, switching, running, over };
  Phase phase_ = Phase::idle;
  bool searching_ = false;  // the drive cleared bit 12 since the start: a new homing runs
  std::uint32_t cycles_ = 0;
};

}  // namespace nck::drives::cia402
