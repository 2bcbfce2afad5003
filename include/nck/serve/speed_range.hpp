#pragma once
// The speeds the live kernel runs at (docs/api.md, "speed"): simulated
// seconds per wall second. Below kMinSpeed a cycle's wall time grows past
// any useful wait (1e-5 meant 100 s per 1 ms cycle) and its deadline
// arithmetic overflows (1e-300); above kMaxSpeed no machine keeps up, so
// `max` says it better. 0 means as fast as possible (`max`).
// Plain constants: the API message parser (built by the fuzzer's clang 14) uses them.

namespace nck::app::serve {

inline constexpr double kMinSpeed = 1e-3;
inline constexpr double kMaxSpeed = 1e4;
inline constexpr double kSpeedMax = 0;  // as fast as possible

// 0 (as fast as possible) or a speed in kMinSpeed..kMaxSpeed.
constexpr bool speed_allowed(double speed) noexcept {
  return speed == kSpeedMax || (speed >= kMinSpeed && speed <= kMaxSpeed);
}

}  // namespace nck::app::serve
