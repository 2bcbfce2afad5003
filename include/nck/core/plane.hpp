#pragma once
// The working plane, one type for the decoder (G17/G18/G19), the frames
// (rotation plane) and the planner (circle plane). Its values are the G
// numbers, so converting to an axis index is always an explicit call.
#include <cstdint>

namespace nck {

enum class Plane : std::uint8_t { g17 = 17, g18 = 18, g19 = 19 };

// Channel axis indices of a plane: the two plane axes (positive rotation
// turns `first` towards `second`) and the tool axis normal to it. The first
// three channel axes are X Y Z; I J K follow the same indices.
// The main axes by name, in the order of plane_axes' indices (also the
// I J K indices): the planner finds them in the channel by these names, the
// decoder maps a cycle's @X/@Y/@Z to them.
inline constexpr const char* kMainAxisNames[] = {"X", "Y", "Z"};

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

}  // namespace nck
