#pragma once
// Fixed-size axis positions for one channel: no heap, safe in the cyclic path.
#include <array>
#include <cstddef>
#include <cstdint>

namespace nck::motion {

// Axes per channel (same value as nck::nc::kMaxAxes; motion does not see nc).
inline constexpr std::size_t kMaxAxes = 32;

// Index = channel axis; mm for linear axes, deg for rotary axes.
using AxisVector = std::array<double, kMaxAxes>;

// Bit i set = channel axis i. Used to say which axes count for the path length.
using AxisMask = std::uint32_t;
inline constexpr AxisMask kAllAxes = 0xFFFF'FFFFu;

constexpr bool in_mask(AxisMask m, std::size_t axis) noexcept {
  return axis < kMaxAxes && ((m >> axis) & 1u) != 0;
}

}  // namespace nck::motion
