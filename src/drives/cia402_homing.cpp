#include "nck/drives/cia402_homing.hpp"

namespace nck::drives::cia402 {

DriveHoming::Outcome DriveHoming::step(bool wanted, std::uint16_t statusword, std::int8_t mode_display) noexcept {
  if (!wanted) {
    phase_ = Phase::idle;
    return Outcome::none;
  }
  ++cycles_;
  switch (phase_) {
    case Phase::idle:
      phase_ = Phase::switching;
      cycles_ = 0;
      searching_ = false;
      return Outcome::none;
    case Phase::switching:
      if (mode_display == static_cast<std::int8_t>(Mode::homing)) phase_ = Phase::running;
      return Outcome::none;
    case Phase::running:
      if (statusword & sw::homing_error) {
        phase_ = Phase::over;
        return Outcome::failed;
      }
      // Bit 12 may still stand from an earlier homing until the drive has
      // seen the start edge: only a search that began counts.
      if (!(statusword & sw::homing_attained)) searching_ = true;
      else if (searching_ && (statusword & sw::target_reached)) {
        phase_ = Phase::over;
        return Outcome::attained;
      }
      return Outcome::none;
    case Phase::over:
      return Outcome::none;
  }
  return Outcome::none;
}

}  // namespace nck::drives::cia402
