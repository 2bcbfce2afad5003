#pragma once
// The acceleration profile of path motions (P-CHAN-00071
// prog_start.slope.profile, #SLOPE [TYPE=..], #SET SLOPE PROFIL[n]): one
// enum whose values are the list's numbers, used unchanged from the
// configuration to the kernel's velocity profile.
#include <cstdint>
#include <optional>
#include <string_view>

namespace nck {

enum class SlopeProfile : std::uint8_t {
  step = 0,    // acceleration steps (velocity trapezoids, jerk unbounded)
  trapez = 1,  // trapezoidal acceleration, jerk bounded by the ramp times
  sin2 = 2,    // sine-square build-up and decay of the acceleration
  hsc = 3,     // trapezoidal across the blocks passed at speed (kernel/hsc_chain.hpp)
};

constexpr bool jerk_limited(SlopeProfile p) noexcept { return p != SlopeProfile::step; }

// The profile a list number names, or nullopt (out of range).
constexpr std::optional<SlopeProfile> slope_from_number(long long n) noexcept {
  if (n < 0 || n > 3) return std::nullopt;
  return static_cast<SlopeProfile>(n);
}

// STEP, TRAPEZ, SIN2, HSC as #SLOPE [TYPE=..] writes them (upper case).
constexpr std::optional<SlopeProfile> slope_from_name(std::string_view s) noexcept {
  if (s == "STEP") return SlopeProfile::step;
  if (s == "TRAPEZ") return SlopeProfile::trapez;
  if (s == "SIN2") return SlopeProfile::sin2;
  if (s == "HSC") return SlopeProfile::hsc;
  return std::nullopt;
}

constexpr std::string_view slope_name(SlopeProfile p) noexcept {
  switch (p) {
    case SlopeProfile::trapez: return "TRAPEZ";
    case SlopeProfile::sin2: return "SIN2";
    case SlopeProfile::hsc: return "HSC";
    case SlopeProfile::step: break;
  }
  return "STEP";
}

}  // namespace nck
