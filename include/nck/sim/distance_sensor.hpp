#pragma once
// The simulated distance sensor of 3D distance control (sim.lis sensor.*):
// the gap between the tool (the tool axis's set point, offset included)
// and a workpiece surface whose height varies along one channel axis
// (FLAT / SINE / STEP / RAMP, plus a tilt), with seeded Gaussian noise, a
// dead time and one injected fault (a dropout of N cycles, a jump — e.g.
// out of the sensor's range — or a frozen value). It only produces
// TickInput values: the kernel never sees this class.
#include <array>
#include <cstdint>

#include "nck/config/machine.hpp"
#include "nck/core/axes.hpp"

namespace nck::sim {

// The surface height at position p along the surface axis, mm (also used by
// the tests to compute the true gap independently of the sensor).
double surface_height_mm(const config::SimConfig& s, double p_mm) noexcept;

class DistanceSensor {
 public:
  DistanceSensor() = default;
  // setup: the sensor of channel ch (axis names resolved to indices).
  DistanceSensor(const config::SimConfig& s, const config::ChannelConfig& ch, double cycle_s);

  // rt: the value for the cycle starting at t_s (from the set points of the
  // cycle before); valid false during a dropout or without a tool axis.
  void sample(double t_s, bool& valid, double& value_mm) noexcept;
  // rt: the set points the kernel just computed.
  void watch(const AxisArray& axis_mcs) noexcept;

 private:
  double noise() noexcept;
  double gap_mm() const noexcept;

  config::SimConfig s_{};  // own copy (setup); the cyclic path only reads it
  bool configured_ = false;
  int tool_axis_ = -1, surface_axis_ = -1;
  double cycle_s_ = 0.001;
  double tool_mm_ = 0, surface_mm_ = 0;  // the two positions the gap depends on
  std::uint64_t rng_ = 1;
  static constexpr std::size_t kMaxDelay = 1000;
  std::array<double, kMaxDelay + 1> delay_{};
  std::size_t head_ = 0, filled_ = 0;
  bool frozen_ = false;
  double frozen_mm_ = 0;
};

}  // namespace nck::sim
