#pragma once
// Basic value types of the frames layer: axis arrays, program and machine
// points kept apart by type, the working plane and the error value.
#include <array>
#include <cstddef>
#include <cstdint>

#include "nck/core/diagnostic.hpp"

namespace nck::frames {

// A channel has at most 32 axes; the first three are the main axes X Y Z in
// G17 order (FCT-C2: CS translations always refer to them in that order).
inline constexpr std::size_t kMaxAxes = 32;
inline constexpr std::size_t kMainAxes = 3;

using AxisValues = std::array<double, kMaxAxes>;  // per channel axis, mm or deg

// Distinct types so a machine position is never fed where a programmed one
// is expected (ARCHITECTURE.md: "distinct types where a mix-up is likely").
struct PcsPoint {
  AxisValues pos_mm{};
};
struct McsPoint {
  AxisValues pos_mm{};
};

enum class Plane : std::uint8_t { g17, g18, g19 };

// Axis indices of a plane: the two plane axes (positive rotation turns
// `first` towards `second`) and the tool axis normal to it.
struct PlaneAxes {
  int first;
  int second;
  int tool;
};
constexpr PlaneAxes plane_axes(Plane p) {
  switch (p) {
    case Plane::g18: return {2, 0, 1};  // Z X, tool axis Y
    case Plane::g19: return {1, 2, 0};  // Y Z, tool axis X
    case Plane::g17: break;
  }
  return {0, 1, 2};  // X Y, tool axis Z
}

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
