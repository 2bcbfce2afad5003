#pragma once
// The sensor filters of 3D distance control (P-CHAN-00825 filter_type):
// fixed-size, allocation-free, noexcept. Each filter starts from a value
// (reset) so that switching on does not ramp in from zero.
#include <array>
#include <cstddef>
#include <cstdint>

namespace nck::distctrl {

// Mean of the last n samples (P-CHAN-00800 n_cycles, 0 <= n < 100; 0 and 1
// pass the value through).
class MovingAverage {
 public:
  static constexpr std::size_t kMaxCycles = 100;
  void setup(std::uint32_t n_cycles) noexcept;
  void reset(double value) noexcept;
  double step(double x) noexcept;

 private:
  std::array<double, kMaxCycles> ring_{};
  std::size_t n_ = 1, head_ = 0;
  double sum_ = 0;
};

// `order` (0..6) equal first-order sections with the corner frequency f0,
// each discretised exactly for a sampled step (y += alpha (x - y),
// alpha = 1 - exp(-2 pi f0 dt)): the slope falls by order * 20 dB/decade
// (P-CHAN-00816/00817). Order 0 passes the value through.
class LowPass {
 public:
  static constexpr std::uint32_t kMaxOrder = 6;
  void setup(std::uint32_t order, double f0_hz, double dt_s) noexcept;
  void reset(double value) noexcept;
  double step(double x) noexcept;
  double alpha() const noexcept { return alpha_; }

 private:
  std::array<double, kMaxOrder> y_{};
  std::uint32_t order_ = 0;
  double alpha_ = 1;
};

// Exponential mean: y += s (x - y), s = P-CHAN-00827 smoothing_factor (the
// share of the newest sample).
class ExpoMean {
 public:
  void setup(double smoothing) noexcept { s_ = smoothing; }
  void reset(double value) noexcept { y_ = value; }
  double step(double x) noexcept { return y_ += s_ * (x - y_); }

 private:
  double s_ = 1, y_ = 0;
};

// Scalar Kalman filter for a value that drifts as a random walk with unit
// process variance per cycle, measured with the standard deviation sigma
// (P-CHAN-00826 kalman_sigma, in units of the process noise): the larger
// sigma, the more it smooths.
class Kalman {
 public:
  void setup(double sigma) noexcept { r_ = sigma * sigma; }
  void reset(double value) noexcept { x_ = value; p_ = 1; }
  double step(double z) noexcept;
  double gain() const noexcept { return k_; }

 private:
  double r_ = 16, x_ = 0, p_ = 1, k_ = 0;
};

enum class FilterKind : std::uint8_t { defaults, moving_average, lowpass, kalman_ma, expo_mean, kalman_expo };

struct FilterSettings {
  FilterKind kind = FilterKind::defaults;
  std::uint32_t n_cycles = 4;
  bool low_pass_enable = false;  // DEFAULT: moving average, then the low pass when enabled
  std::uint32_t order = 4;
  double f0_hz = 25;
  double smoothing = 0.7;
  double kalman_sigma = 4;
};

// The selected chain: DEFAULT = moving average (+ low pass when enabled),
// MOVING_AVERAGE, LOWPASS, KALMAN_MA = Kalman then moving average, EXPO_MEAN,
// KALMAN_EXPO = Kalman then exponential mean.
class SensorFilter {
 public:
  void setup(const FilterSettings& s, double dt_s) noexcept;
  void reset(double value) noexcept;
  double step(double x) noexcept;

 private:
  FilterSettings s_{};
  MovingAverage ma_;
  LowPass lp_;
  ExpoMean expo_;
  Kalman kalman_;
};

}  // namespace nck::distctrl
