#pragma once
// Speed command value of a speed-controlled spindle (FCT-S1 2.2.4): the
// drive receives v_reso_num increments per v_reso_denom (0.001 deg) per time
// base (antr.v_time_base: 0 minute, 1 second, 2 interpolation cycle).
#include "nck/config/machine.hpp"

namespace nck::spindle {

// The three drive parameters above, as one value.
struct SpeedScaling {
  std::uint32_t increments_num = 1;    // v_reso_num
  std::uint32_t increments_denom = 36; // v_reso_denom
  std::uint32_t time_base = 0;         // v_time_base
};

// Drive output value for a signed speed in rpm; 0 when the scaling is unusable
// (denominator 0, unknown time base, non-finite input). // rt
double drive_output_value(std::uint32_t v_reso_num, std::uint32_t v_reso_denom,
                          std::uint32_t v_time_base, double speed_rpm, double cycle_s) noexcept;

inline double drive_output_value(const SpeedScaling& sc, double speed_rpm, double cycle_s) noexcept {
  return drive_output_value(sc.increments_num, sc.increments_denom, sc.time_base, speed_rpm, cycle_s);
}

inline double drive_output_value(const config::AxisConfig& ax, double speed_rpm, double cycle_s) noexcept {
  return drive_output_value(ax.speed_increments_num, ax.speed_increments_denom, ax.speed_time_base, speed_rpm, cycle_s);
}

}  // namespace nck::spindle
