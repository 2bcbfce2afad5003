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

}  // namespace nck::app
