#include "nck/distctrl/filters.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace nck::distctrl {

void MovingAverage::setup(std::uint32_t n_cycles) noexcept {
  n_ = std::clamp<std::size_t>(n_cycles, 1, kMaxCycles);
  reset(0);
}

void MovingAverage::reset(double value) noexcept {
  for (std::size_t i = 0; i < n_; ++i) ring_[i] = value;
  sum_ = value * static_cast<double>(n_);
  head_ = 0;
}

double MovingAverage::step(double x) noexcept {
  sum_ += x - ring_[head_];
  ring_[head_] = x;
  head_ = (head_ + 1) % n_;
  return sum_ / static_cast<double>(n_);
}

void LowPass::setup(std::uint32_t order, double f0_hz, double dt_s) noexcept {
  order_ = std::min(order, kMaxOrder);
  // f0 = 0 would never move: treat it as no filter.
  alpha_ = f0_hz > 0 ? 1.0 - std::exp(-2.0 * std::numbers::pi * f0_hz * dt_s) : 1.0;
  reset(0);
}

void LowPass::reset(double value) noexcept { y_.fill(value); }

double LowPass::step(double x) noexcept {
  for (std::uint32_t i = 0; i < order_; ++i) {
    y_[i] += alpha_ * (x - y_[i]);
    x = y_[i];
  }
  return x;
}

double Kalman::step(double z) noexcept {
  const double p_prior = p_ + 1.0;  // unit process variance per cycle
  k_ = p_prior / (p_prior + r_);
  x_ += k_ * (z - x_);
  p_ = (1.0 - k_) * p_prior;
  return x_;
}

void SensorFilter::setup(const FilterSettings& s, double dt_s) noexcept {
  s_ = s;
  ma_.setup(s.n_cycles);
  lp_.setup(s.order, s.f0_hz, dt_s);
  expo_.setup(s.smoothing);
  kalman_.setup(s.kalman_sigma);
}

void SensorFilter::reset(double value) noexcept {
  ma_.reset(value);
  lp_.reset(value);
  expo_.reset(value);
  kalman_.reset(value);
}

double SensorFilter::step(double x) noexcept {
  switch (s_.kind) {
    case FilterKind::moving_average: return ma_.step(x);
    case FilterKind::lowpass: return lp_.step(x);
    case FilterKind::kalman_ma: return ma_.step(kalman_.step(x));
    case FilterKind::expo_mean: return expo_.step(x);
    case FilterKind::kalman_expo: return expo_.step(kalman_.step(x));
    case FilterKind::defaults: break;
  }
  const double y = ma_.step(x);
  return s_.low_pass_enable ? lp_.step(y) : y;
}

}  // namespace nck::distctrl
