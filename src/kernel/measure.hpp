#pragma once
// The result of a G100 measuring run: written by the channel in the cycle
// (no heap), read by the planner and the decoder's variables afterwards.
#include <cstdint>

#include "nck/motion/axis_vector.hpp"

namespace nck::kernel {

struct MeasureResult {
  std::uint64_t count = 0;       // finished G100 runs
  bool triggered = false;        // the probe switched
  motion::AxisVector mcs{};      // where the axes stopped (the switching point when triggered)
  // program coordinates, filled in when the planner takes the result over
  motion::AxisVector measured_pcs{};
  motion::AxisVector target_pcs{};
};

}  // namespace nck::kernel
