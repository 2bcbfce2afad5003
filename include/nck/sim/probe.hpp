#pragma once
// A simulated touch probe (sim.lis probe.axis / probe.position): it switches
// when its axis's set point passes the switching position, and latches every
// axis's position at that instant (interpolated within the cycle, as a
// drive's touch-probe latch does). The kernel sees the switch one cycle
// later, like any input. rt: watch() never allocates or throws.
#include <array>
#include <cstddef>

#include "nck/config/machine.hpp"
#include "nck/core/axes.hpp"

namespace nck::sim {

class Probe {
 public:
  using Positions = AxisArray;

  Probe() = default;
  // setup: axis = channel axis index (-1: this channel has no probe).
  Probe(int axis, double switch_pos_mm, std::size_t n_axes) noexcept
      : axis_(axis), switch_pos_mm_(switch_pos_mm), n_axes_(n_axes) {}

  // rt: the set points of the cycle just computed. True when the probe
  // switched during it; latched() then holds the positions.
  bool watch(const Positions& now) noexcept { return axis_ >= 0 && watch_axis(now); }
  const Positions& latched() const noexcept { return latched_; }

 private:
  bool watch_axis(const Positions& now) noexcept;
  int axis_ = -1;
  double switch_pos_mm_ = 0;
  std::size_t n_axes_ = 0;
  bool started_ = false;
  Positions last_{};
  Positions latched_{};
};

}  // namespace nck::sim
