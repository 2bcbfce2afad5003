#pragma once
// Pure spindle geometry and monitoring rules (FCT-S1 2.3.2, 2.6): modulo
// wrapping, the travel of an M19 move, the preferred-direction check and the
// speed-reached / zero-speed tests.
#include <cstdint>
#include <expected>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"

namespace nck::spindle {

enum class Direction : std::int8_t { none = 0, positive = 1, negative = -1 };  // M3 +, M4 -

namespace detail {
// wrap_modulo by its definition, through fmod.
double wrap_modulo_by_fmod(double pos_deg, double lo_deg, double hi_deg) noexcept;
}  // namespace detail

// pos wrapped into [lo, hi); returns lo when the range is empty or pos not
// finite. A turning spindle leaves its range by less than a turn per cycle:
// inline, one addition or subtraction gives fmod's result bit for bit (fmod
// returns x itself inside (-range, range), and x - range is exact for x in
// [range, 2 range)); anything else goes through fmod. Always inline: a
// turning spindle wraps three times a cycle, and GCC keeps it out of line. // rt
[[gnu::always_inline]] inline double wrap_modulo(double pos_deg, double lo_deg, double hi_deg) noexcept {
  const double range = hi_deg - lo_deg, d = pos_deg - lo_deg;
  if (range > 0 && range < 1e300) {
    if (d >= 0 && d < range) return lo_deg + d;
    if (d >= range && d < 2 * range) return lo_deg + (d - range);
    if (d < 0 && d > -range) {
      const double r = d + range;
      return lo_deg + (r >= range ? 0.0 : r);
    }
  }
  return detail::wrap_modulo_by_fmod(pos_deg, lo_deg, hi_deg);
}

// False when a preferred direction is set and `dir` is the other one. // rt
constexpr bool direction_allowed(Direction preferred, Direction dir) noexcept {
  return preferred == Direction::none || dir == Direction::none || dir == preferred;
}

// Error 60254 when a preferred direction is configured (vorz_richtung) and
// `dir` is the other one; Direction::none always passes. // rt
std::expected<void, ErrorId> check_preferred_direction(const config::AxisConfig& ax, Direction dir) noexcept;

// The direction the configuration forces, or none. // rt
Direction preferred_direction(const config::AxisConfig& ax) noexcept;

// Signed travel in degrees from `current` to `target` (both wrapped into
// [lo, hi) first) for an M19 move:
// - programmed M3/M4: in that direction, 0 <= |travel| < range;
// - none, rotating (speed != 0): in the current direction;
// - none, standstill: the shorter way (a tie goes positive). // rt
double m19_travel_deg(double current_deg, double target_deg, Direction programmed,
                      double current_speed_deg_s, double lo_deg, double hi_deg) noexcept;

// Speed reached: |act - cmd| <= tolerance_permille * 0.1 % * |cmd| (vb_prozent, P-AXIS-00217,
// default 100 = +-10 %). Signed, so M4 speed never "reaches" an M3 command. // rt
bool speed_reached(double act_rpm, double cmd_rpm, double tolerance_permille) noexcept;

// Zero speed: |act| strictly below vb_min_null (P-AXIS-00216, deg/s). // rt
bool zero_speed(double act_deg_s, double vb_min_null_deg_s) noexcept;

inline constexpr double kDegPerSPerRpm = 6.0;  // 1 rpm = 360 deg / 60 s
constexpr double rpm_to_deg_s(double rpm) { return rpm * kDegPerSPerRpm; }
constexpr double deg_s_to_rpm(double deg_s) { return deg_s / kDegPerSPerRpm; }

}  // namespace nck::spindle
