#pragma once
// MCS = rot * PCS on the main axes (X Y Z) + shift on every axis: the map of
// one block's path, evaluated once at planning time and applied to every
// set point of the block in the cycle.
#include <array>
#include <cstddef>

#include "nck/frames/rotation.hpp"
#include "nck/motion/axis_vector.hpp"

namespace nck::kernel {

struct AffineMap {
  std::array<int, 3> main{-1, -1, -1};  // channel index of X, Y, Z (-1 = none)
  frames::Mat3 rot = frames::identity3();
  motion::AxisVector shift{};
  bool pure_translation = true;
  // The same map: main axes, rotation and shift (pure_translation follows from rot).
  bool operator==(const AffineMap& o) const { return main == o.main && rot == o.rot && shift == o.shift; }
  void apply(const motion::AxisVector& pcs, motion::AxisVector& mcs, std::size_t n) const noexcept;  // rt
};

}  // namespace nck::kernel
