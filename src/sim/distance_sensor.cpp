#include "nck/sim/distance_sensor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace nck::sim {

double surface_height_mm(const config::SimConfig& s, double p_mm) noexcept {
  const double x = p_mm - s.surface_start_mm;
  double h = s.surface_height_mm + std::tan(s.surface_tilt_deg * std::numbers::pi / 180.0) * x;
  switch (s.surface) {
    case config::SurfaceKind::sine: h += s.surface_amplitude_mm * std::sin(2 * std::numbers::pi * x / s.surface_wavelength_mm); break;
    case config::SurfaceKind::step: h += x >= 0 ? s.surface_amplitude_mm : 0.0; break;
    case config::SurfaceKind::ramp: h += x > 0 ? s.surface_amplitude_mm * x / s.surface_wavelength_mm : 0.0; break;
    case config::SurfaceKind::flat: break;
  }
  if (s.hole_length_mm > 0 && p_mm >= s.hole_start_mm && p_mm < s.hole_start_mm + s.hole_length_mm)
    h -= s.hole_depth_mm;
  return h;
}

namespace {
int axis_index(const config::ChannelConfig& ch, const std::string& name) {
  for (std::size_t j = 0; j < ch.axes.size() && j < kMaxAxes; ++j)
    if (ch.axes[j].name == name) return static_cast<int>(j);
  return -1;
}
}  // namespace

DistanceSensor::DistanceSensor(const config::SimConfig& s, const config::ChannelConfig& ch, double cycle_s)
    : s_(s),
      configured_(true),
      tool_axis_(axis_index(ch, s.sensor_tool_axis)),
      surface_axis_(axis_index(ch, s.surface_axis)),
      cycle_s_(cycle_s),
      rng_(0x9E3779B97F4A7C15ull ^ (static_cast<std::uint64_t>(s.noise_seed) + 1) * 0xBF58476D1CE4E5B9ull) {}

// xorshift64* and Box-Muller: the same seed gives the same run everywhere.
double DistanceSensor::noise() noexcept {
  auto next = [this] {
    rng_ ^= rng_ >> 12;
    rng_ ^= rng_ << 25;
    rng_ ^= rng_ >> 27;
    return static_cast<double>((rng_ * 2685821657736338717ull) >> 11) * 0x1.0p-53;
  };
  const double u1 = std::max(next(), 1e-300), u2 = next();
  return std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
}

double DistanceSensor::gap_mm() const noexcept {
  return tool_mm_ - surface_height_mm(s_, surface_mm_);
}

void DistanceSensor::watch(const AxisArray& axis_mcs) noexcept {
  if (tool_axis_ >= 0) tool_mm_ = axis_mcs[static_cast<std::size_t>(tool_axis_)];
  if (surface_axis_ >= 0) surface_mm_ = axis_mcs[static_cast<std::size_t>(surface_axis_)];
}

void DistanceSensor::sample(double t_s, bool& valid, double& value_mm) noexcept {
  valid = false;
  if (!configured_ || tool_axis_ < 0) return;
  double v = gap_mm();
  if (s_.noise_sigma_mm > 0) v += s_.noise_sigma_mm * noise();
  // Dead time: the value seen now was measured delay_cycles ago.
  const std::size_t delay = std::min<std::size_t>(s_.sensor_delay_cycles, kMaxDelay);
  delay_[head_] = v;
  head_ = (head_ + 1) % (kMaxDelay + 1);
  filled_ = std::min(filled_ + 1, kMaxDelay + 1);
  if (filled_ <= delay) v = delay_[0];
  else v = delay_[(head_ + kMaxDelay - delay) % (kMaxDelay + 1)];
  // One fault from fault_time on, for fault_cycles cycles (0: to the end).
  const double end_s = s_.fault_time_s + s_.fault_cycles * cycle_s_;
  const bool faulty = s_.fault != config::SensorFault::none && t_s >= s_.fault_time_s - 1e-9 &&
                      (s_.fault_cycles == 0 || t_s < end_s - 1e-9);
  if (!faulty) frozen_ = false;
  if (faulty && s_.fault == config::SensorFault::dropout) return;
  if (faulty && s_.fault == config::SensorFault::jump) v += s_.fault_value_mm;
  if (faulty && s_.fault == config::SensorFault::freeze) {
    if (!frozen_) frozen_mm_ = v;
    frozen_ = true;
    v = frozen_mm_;
  }
  valid = true;
  value_mm = v;
}

}  // namespace nck::sim
