#pragma once
// What the channel found in a G100 measuring run (sent back to preparation
// as feedback; the planner adds the program coordinates).
#include "nck/motion/axis_vector.hpp"

namespace nck::kernel {

struct MeasureResult {
  bool triggered = false;        // the probe switched
  motion::AxisVector mcs{};      // where the axes stopped (the switching point when triggered)
};

}  // namespace nck::kernel
