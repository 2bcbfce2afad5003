#pragma once
// Which of a channel's axes a backplot draws as X, Y and Z: the axes of
// those names; a channel without them (the twin-spindle machine's X, Y1,
// Z1) takes its first linear axes. The report and `nck diff` agree on it.
#include <array>
#include <string>

#include "nck/config/machine.hpp"

namespace nck::app {

// A rotary axis by its name (A, B, C...): not drawn on a backplot.
bool is_rotary_name(const std::string& name);
// Channel axis index of the backplot's X, Y, Z (-1: none).
std::array<int, 3> backplot_axes(const config::ChannelConfig& ch);

// The software limits (kenngr.swe_neg/swe_pos, machine coordinates, mm) of
// the backplot's X, Y, Z as the planner checks them: an axis without a list
// has the defaults; no axis: {0, 0}. The report's 3D view draws them as a box.
struct SoftLimits {
  std::array<double, 3> min_mm{}, max_mm{};
};
SoftLimits backplot_limits(const config::Machine& m, const config::ChannelConfig& ch, const std::array<int, 3>& axis);

}  // namespace nck::app
