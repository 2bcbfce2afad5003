#pragma once
// Basic value types of the frames layer: axis arrays, program and machine
// points kept apart by type, the working plane and the error value.
#include <array>
#include <cstddef>
#include <cstdint>

#include "nck/core/axes.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/core/plane.hpp"

namespace nck::frames {

// A channel has at most kMaxAxes axes (core/axes.hpp); the first three are
// the main axes X Y Z in G17 order (FCT-C2: CS translations always refer to
// them in that order).
inline constexpr std::size_t kMainAxes = 3;

using AxisValues = AxisArray;  // per channel axis, mm or deg

// Distinct types so a machine position is never fed where a programmed one
// is expected (a mix-up the compiler should catch).
struct PcsPoint {
  AxisValues pos_mm{};
};
struct McsPoint {
  AxisValues pos_mm{};
};

// The working plane and its axes are core's Plane / plane_axes (one type
// for decoder, frames and planner).

// What went wrong in a frames operation. No heap: the cyclic path may hold it.
// `axis` is the channel axis index (-1 = none), `detail` an id or index that
// makes the message specific (CS id, zero-offset index ...).
struct FrameError {
  ErrorId id{};
  int axis = -1;
  int detail = 0;
};

// Turns a FrameError into a located Diagnostic (setup / decoder side).
Diagnostic to_diagnostic(const FrameError& e, SourceLoc loc);

}  // namespace nck::frames
