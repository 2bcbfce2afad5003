#pragma once
// Fixed-size axis positions for one channel: no heap, safe in the cyclic path.
#include <cstddef>
#include <cstdint>

#include "nck/core/axes.hpp"

namespace nck::motion {

// Index = channel axis; mm for linear axes, deg for rotary axes. The motion
// layer's name for core's AxisArray (kMaxAxes axes per channel).
using AxisVector = AxisArray;

// Bit i set = channel axis i. Used to say which axes count for the path length.
using AxisMask = std::uint32_t;
static_assert(kMaxAxes <= 32, "AxisMask has one bit per channel axis");
inline constexpr AxisMask kAllAxes = 0xFFFF'FFFFu;

constexpr bool in_mask(AxisMask m, std::size_t axis) noexcept {
  return axis < kMaxAxes && ((m >> axis) & 1u) != 0;
}

}  // namespace nck::motion
