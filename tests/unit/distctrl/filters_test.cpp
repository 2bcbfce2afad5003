// The sensor filters against reference responses computed here in closed form.
#include "nck/distctrl/filters.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace nck::distctrl {
namespace {

constexpr double kDt = 0.001;

TEST(MovingAverage, StepRisesLinearlyOverNCycles) {
  MovingAverage f;
  f.setup(4);
  f.reset(0);
  // A unit step enters one sample per cycle: k/4 after k cycles, 1 from the 4th on.
  for (int k = 1; k <= 8; ++k) EXPECT_DOUBLE_EQ(f.step(1.0), std::min(k, 4) / 4.0) << k;
}

TEST(MovingAverage, ZeroAndOneCyclesPassThrough) {
  for (std::uint32_t n : {0u, 1u}) {
    MovingAverage f;
    f.setup(n);
    f.reset(3);
    EXPECT_DOUBLE_EQ(f.step(7.5), 7.5);
  }
}

TEST(MovingAverage, NinetyNineCyclesIsTheLargestWindow) {
  MovingAverage f;
  f.setup(99);
  f.reset(0);
  double y = 0;
  for (int k = 1; k <= 99; ++k) y = f.step(99.0);
  EXPECT_NEAR(y, 99.0, 1e-9);
  f.reset(0);
  EXPECT_NEAR(f.step(99.0), 1.0, 1e-12);  // 99/99 after one cycle
}

TEST(LowPass, FirstOrderStepIsOneMinusDecay) {
  LowPass f;
  const double f0 = 25;
  f.setup(1, f0, kDt);
  f.reset(0);
  const double a = std::exp(-2 * std::numbers::pi * f0 * kDt);  // pole
  for (int k = 1; k <= 50; ++k) EXPECT_NEAR(f.step(1.0), 1 - std::pow(a, k), 1e-12) << k;
}

// Two equal first-order sections: the sampled step response is
// 1 - a^k - k (1 - a) a^k, which approaches the continuous
// 1 - (1 + t/tau) e^(-t/tau) with tau = 1 / (2 pi f0) for small dt.
TEST(LowPass, SecondOrderStepMatchesClosedForm) {
  LowPass f;
  const double f0 = 10;
  f.setup(2, f0, kDt);
  f.reset(0);
  const double a = std::exp(-2 * std::numbers::pi * f0 * kDt);
  const double tau = 1 / (2 * std::numbers::pi * f0);
  for (int k = 1; k <= 200; ++k) {
    const double y = f.step(1.0);
    EXPECT_NEAR(y, 1 - std::pow(a, k) - k * (1 - a) * std::pow(a, k), 1e-12) << k;
    const double t = k * kDt;
    EXPECT_NEAR(y, 1 - (1 + t / tau) * std::exp(-t / tau), 0.02) << k;
  }
}

// Order n: the response to a sine at f0 is damped by (1/sqrt 2)^n (each
// section -3 dB at its corner), and the slope falls 20 dB/decade per order.
TEST(LowPass, AmplitudeAtCornerFallsWithOrder) {
  const double f0 = 20, dt = 1e-4;
  for (std::uint32_t order = 0; order <= 6; ++order) {
    LowPass f;
    f.setup(order, f0, dt);
    f.reset(0);
    double peak = 0;
    const int n = static_cast<int>(2.0 / dt);
    for (int k = 0; k < n; ++k) {
      const double y = f.step(std::sin(2 * std::numbers::pi * f0 * k * dt));
      if (k > n / 2) peak = std::max(peak, std::fabs(y));
    }
    EXPECT_NEAR(peak, std::pow(std::sqrt(0.5), order), 0.01) << order;
  }
}

TEST(ExpoMean, StepFollowsTheSmoothingFactor) {
  ExpoMean f;
  f.setup(0.5);  // the seed's example: the newest value counts 50 %
  f.reset(0);
  EXPECT_DOUBLE_EQ(f.step(1.0), 0.5);
  EXPECT_DOUBLE_EQ(f.step(1.0), 0.75);
  f.setup(0.7);  // P-CHAN-00827 default
  f.reset(0);
  for (int k = 1; k <= 10; ++k) EXPECT_NEAR(f.step(1.0), 1 - std::pow(0.3, k), 1e-12);
}

// Random walk with unit process variance, measurement variance sigma^2:
// the a-priori variance settles at P = (1 + sqrt(1 + 4 sigma^2)) / 2 and the
// gain at K = P / (P + sigma^2).
TEST(Kalman, GainSettlesAtTheRiccatiSolution) {
  for (double sigma : {1.0, 4.0, 100.0}) {
    Kalman f;
    f.setup(sigma);
    f.reset(0);
    for (int k = 0; k < 20000; ++k) f.step(0.0);
    const double r = sigma * sigma;
    const double p = (1 + std::sqrt(1 + 4 * r)) / 2;
    EXPECT_NEAR(f.gain(), p / (p + r), 1e-9) << sigma;
  }
  Kalman f;
  f.setup(4);  // P-CHAN-00826 default: K = 0.2207..
  f.reset(0);
  for (int k = 0; k < 1000; ++k) f.step(0.0);
  EXPECT_NEAR(f.gain(), 0.2207, 1e-4);
}

TEST(Kalman, LargerSigmaSmoothsMore) {
  Kalman a, b;
  a.setup(1);
  b.setup(50);
  a.reset(0);
  b.reset(0);
  for (int k = 0; k < 5000; ++k) {
    a.step(0);
    b.step(0);
  }
  EXPECT_LT(b.step(1.0), a.step(1.0));
}

TEST(SensorFilter, ChainsAreComposedInOrder) {
  FilterSettings s;
  s.kalman_sigma = 4;
  s.n_cycles = 2;
  s.smoothing = 0.5;
  // KALMAN_MA: the Kalman output, averaged over n_cycles.
  s.kind = FilterKind::kalman_ma;
  SensorFilter f;
  f.setup(s, kDt);
  f.reset(0);
  Kalman k;
  k.setup(4);
  k.reset(0);
  MovingAverage m;
  m.setup(2);
  m.reset(0);
  for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(f.step(1.0), m.step(k.step(1.0)));
  s.kind = FilterKind::kalman_expo;
  f.setup(s, kDt);
  f.reset(0);
  k.reset(0);
  ExpoMean e;
  e.setup(0.5);
  e.reset(0);
  for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(f.step(1.0), e.step(k.step(1.0)));
  // DEFAULT: moving average, then the low pass only when enabled.
  s.kind = FilterKind::defaults;
  s.low_pass_enable = false;
  f.setup(s, kDt);
  f.reset(0);
  EXPECT_DOUBLE_EQ(f.step(1.0), 0.5);
  s.low_pass_enable = true;
  s.order = 1;
  s.f0_hz = 25;
  f.setup(s, kDt);
  f.reset(0);
  EXPECT_NEAR(f.step(1.0), 0.5 * (1 - std::exp(-2 * std::numbers::pi * 25 * kDt)), 1e-12);
}

TEST(SensorFilter, ResetStartsSteady) {
  for (auto kind : {FilterKind::defaults, FilterKind::moving_average, FilterKind::lowpass, FilterKind::kalman_ma,
                    FilterKind::expo_mean, FilterKind::kalman_expo}) {
    FilterSettings s;
    s.kind = kind;
    SensorFilter f;
    f.setup(s, kDt);
    f.reset(2.5);
    EXPECT_DOUBLE_EQ(f.step(2.5), 2.5) << static_cast<int>(kind);
  }
}

}  // namespace
}  // namespace nck::distctrl
