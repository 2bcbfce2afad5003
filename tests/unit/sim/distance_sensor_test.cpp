// The simulated distance sensor: surface, noise, dead time and faults
// against values worked out by hand.
#include "nck/sim/distance_sensor.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace nck::sim {
namespace {

config::ChannelConfig xyz() {
  config::ChannelConfig ch;
  for (const char* n : {"X", "Y", "Z"}) {
    config::ChannelAxis a;
    a.name = n;
    ch.axes.push_back(a);
  }
  return ch;
}

TEST(DistanceSensor, SurfaceKindsTiltAndHole) {
  config::SimConfig s;
  s.surface = config::SurfaceKind::sine;
  s.surface_amplitude_mm = 2;
  s.surface_wavelength_mm = 200;
  s.surface_tilt_deg = 1;
  EXPECT_NEAR(surface_height_mm(s, 50), std::tan(std::numbers::pi / 180) * 50 + 2, 1e-12);
  s.hole_start_mm = 40;
  s.hole_length_mm = 20;
  s.hole_depth_mm = 20;
  EXPECT_NEAR(surface_height_mm(s, 50), std::tan(std::numbers::pi / 180) * 50 + 2 - 20, 1e-12);
  EXPECT_NEAR(surface_height_mm(s, 60), std::tan(std::numbers::pi / 180) * 60 + 2 * std::sin(0.6 * std::numbers::pi), 1e-12);
  config::SimConfig r;
  r.surface = config::SurfaceKind::ramp;
  r.surface_amplitude_mm = 1;
  r.surface_wavelength_mm = 10;
  r.surface_start_mm = 5;
  EXPECT_DOUBLE_EQ(surface_height_mm(r, 4), 0.0);
  EXPECT_DOUBLE_EQ(surface_height_mm(r, 10), 0.5);
  r.surface = config::SurfaceKind::step;
  EXPECT_DOUBLE_EQ(surface_height_mm(r, 5), 1.0);
}

TEST(DistanceSensor, GapDelayAndFaults) {
  config::SimConfig s;
  s.surface_height_mm = 0.5;
  s.sensor_delay_cycles = 2;
  s.fault = config::SensorFault::dropout;
  s.fault_time_s = 0.010;
  s.fault_cycles = 3;
  DistanceSensor d(s, xyz(), 0.001);
  AxisArray p{};
  bool valid = false;
  double v = 0;
  // Z steps 2, 3, 4 ... : the value seen lags two cycles (the first values repeat the first).
  for (int k = 0; k < 6; ++k) {
    p[2] = 2.0 + k;
    d.watch(p);
    d.sample(0.001 * k, valid, v);
    ASSERT_TRUE(valid);
    EXPECT_DOUBLE_EQ(v, 1.5 + std::max(0, k - 2)) << k;
  }
  for (int k = 10; k < 14; ++k) {
    d.sample(0.001 * k, valid, v);
    EXPECT_EQ(valid, k >= 13) << k;  // three cycles without a value
  }
  s.fault = config::SensorFault::jump;
  s.fault_value_mm = 7;
  s.fault_cycles = 0;  // to the end
  s.sensor_delay_cycles = 0;
  DistanceSensor j(s, xyz(), 0.001);
  p[2] = 2;
  j.watch(p);
  j.sample(0.009, valid, v);
  EXPECT_DOUBLE_EQ(v, 1.5);
  j.sample(0.5, valid, v);
  EXPECT_DOUBLE_EQ(v, 8.5);
}

TEST(DistanceSensor, SeededNoiseIsRepeatableWithItsSigma) {
  config::SimConfig s;
  s.noise_sigma_mm = 0.01;
  s.noise_seed = 15;
  DistanceSensor a(s, xyz(), 0.001), b(s, xyz(), 0.001);
  bool va = false, vb = false;
  double x = 0, y = 0, sum = 0, sum2 = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    a.sample(0, va, x);
    b.sample(0, vb, y);
    ASSERT_EQ(x, y);
    sum += x;
    sum2 += x * x;
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0.0, 0.0005);
  EXPECT_NEAR(sd, 0.01, 0.0005);
}

}  // namespace
}  // namespace nck::sim
