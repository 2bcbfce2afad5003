#pragma once
// Cutting-edge position of a turning tool (tool list wz[i].srk_lage, 1..9):
// where the theoretical tool tip P lies relative to the centre S of the
// nose radius, in the plane of the longitudinal axis Z (first, "a") and the
// facing axis X (second, "b"), +Z to the right and +X up as drawn for a
// tool behind the turning centre (docs/decisions.md, "Tool radius
// compensation", cutting-edge position). The tool offsets are measured to P, so
// P is the point that follows the program; with compensation the nose centre S
// runs on the offset contour and P = S + tip_from_centre().
#include <cstdint>

#include "nck/motion/offset_contour.hpp"

namespace nck::motion::trc {

// P - S in units of the nose radius; 0 and 9 (and anything else) = S itself.
constexpr Vec2 tip_direction(std::uint32_t position) {
  switch (position) {
    case 1: return {1, -1};
    case 2: return {-1, -1};
    case 3: return {-1, 1};
    case 4: return {1, 1};
    case 5: return {1, 0};
    case 6: return {0, -1};
    case 7: return {-1, 0};
    case 8: return {0, 1};
    default: return {0, 0};
  }
}

// P - S in mm for a nose radius (its magnitude: a negative radius only swaps the side).
constexpr Vec2 tip_from_centre(std::uint32_t position, double nose_radius_mm) {
  const double r = nose_radius_mm < 0 ? -nose_radius_mm : nose_radius_mm;
  return r * tip_direction(position);
}

}  // namespace nck::motion::trc
