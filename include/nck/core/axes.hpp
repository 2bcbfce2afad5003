#pragma once
// The one axis count and fixed axis array of the whole kernel. Every layer
// (nc words, frames, motion, config lists, kernel) sizes its per-axis arrays
// from here, so the layers cannot disagree on how many axes a channel has.
#include <array>
#include <cstddef>

namespace nck {

// Axes per channel; index = channel axis.
inline constexpr std::size_t kMaxAxes = 32;

// One value per channel axis: mm for linear axes, deg for rotary axes.
using AxisArray = std::array<double, kMaxAxes>;

}  // namespace nck
