// Seed FCT-S1 2.8.4: curve formulas and the coefficient fitting with the
// seed's tables (16000/8000/4000/2000 deg/s^2 at 12000..48000 deg/s).
#include <gtest/gtest.h>

#include <cmath>

#include <array>

#include "nck/spindle/accel_curve.hpp"

namespace nck::spindle {
namespace {

constexpr double kNGrenz = 12000, kAKonst = 16000;
constexpr std::array<CurvePoint, 4> kTable{{{12000, 16000}, {24000, 8000}, {36000, 4000}, {48000, 2000}}};

config::AccelCurve polynomial_curve(const Coefficients& c, double a_min) {
  config::AccelCurve k;
  k.type = 2;
  k.limit_speed_deg_s = kNGrenz;
  k.const_accel_deg_s2 = kAKonst;
  k.a_min_deg_s2 = a_min;
  k.b1 = c.b1; k.b2 = c.b2; k.b3 = c.b3;
  return k;
}

TEST(AccelCurveFit, PolynomialGivesTheSeedCoefficients) {
  auto c = fit_polynomial(kNGrenz, kAKonst, kTable);  // P1 at n_grenz is skipped
  ASSERT_TRUE(c.has_value()) << c.error();
  EXPECT_NEAR(c->b3, -1.92901234E-10, 1e-18);
  EXPECT_NEAR(c->b2, 2.08333333E-5, 1e-13);
  EXPECT_NEAR(c->b1, -0.88888888, 1e-8);
}

TEST(AccelCurveFit, PolynomialReproducesTheTable) {
  auto c = fit_polynomial(kNGrenz, kAKonst, kTable);
  ASSERT_TRUE(c.has_value());
  auto k = polynomial_curve(*c, 0);
  for (const auto& p : kTable) EXPECT_NEAR(curve_accel_deg_s2(k, p.speed_deg_s), p.accel_deg_s2, 1e-6);
  // The printed (rounded) coefficients of the seed's parameter example too.
  auto printed = polynomial_curve({-0.88888888, 2.08333333E-5, -1.92901234E-10}, 2000);
  EXPECT_NEAR(curve_accel_deg_s2(printed, 24000), 8000, 0.01);
  EXPECT_NEAR(curve_accel_deg_s2(printed, 36000), 4000, 0.01);
  EXPECT_NEAR(curve_accel_deg_s2(printed, 48000), 2000, 0.05);
}

TEST(AccelCurveFit, HyperbolaGivesTheSeedCoefficients) {
  const std::array<CurvePoint, 2> pts{{{24000, 8000}, {36000, 4000}}};
  auto c = fit_hyperbola(kNGrenz, kAKonst, pts);
  ASSERT_TRUE(c.has_value()) << c.error();
  EXPECT_NEAR(c->b2, 0.4166666, 1e-7);
  EXPECT_NEAR(c->b3, 0.02857142, 1e-8);  // FCT-S1 §2.8.4.1's result; its list example prints -2.857142E-2
  EXPECT_NEAR(c->b1, 22857.14, 0.01);
}

TEST(AccelCurveFit, HyperbolaReproducesItsPoints) {
  const std::array<CurvePoint, 3> pts{{{12000, 16000}, {24000, 8000}, {36000, 4000}}};
  auto c = fit_hyperbola(kNGrenz, kAKonst, pts);
  ASSERT_TRUE(c.has_value());
  config::AccelCurve k;
  k.type = 1; k.limit_speed_deg_s = kNGrenz; k.const_accel_deg_s2 = kAKonst;
  k.b1 = c->b1; k.b2 = c->b2; k.b3 = c->b3;
  EXPECT_NEAR(curve_accel_deg_s2(k, 12000), 16000, 1e-6);
  EXPECT_NEAR(curve_accel_deg_s2(k, 24000), 8000, 1e-6);
  EXPECT_NEAR(curve_accel_deg_s2(k, 36000), 4000, 1e-6);
  // 3 parameters cannot hit the 4th table point: 22857.14 / 10.714 = 2133.3.
  EXPECT_NEAR(curve_accel_deg_s2(k, 48000), 2133.33, 0.01);
  EXPECT_NEAR(curve_accel_deg_s2(k, 5000), 16000, 0);  // a_konst below n_grenz
}

TEST(AccelCurveFit, BadInputIsAnErrorNotACrash) {
  const std::array<CurvePoint, 2> two{{{24000, 8000}, {36000, 4000}}};
  EXPECT_FALSE(fit_polynomial(kNGrenz, kAKonst, two).has_value());            // count
  EXPECT_FALSE(fit_hyperbola(kNGrenz, kAKonst, kTable).has_value());          // count
  const std::array<CurvePoint, 2> same{{{24000, 8000}, {24000, 4000}}};
  EXPECT_FALSE(fit_hyperbola(kNGrenz, kAKonst, same).has_value());            // duplicate speed
  const std::array<CurvePoint, 2> below{{{6000, 8000}, {36000, 4000}}};
  EXPECT_FALSE(fit_hyperbola(kNGrenz, kAKonst, below).has_value());
  const std::array<CurvePoint, 2> neg{{{24000, -8000}, {36000, 4000}}};
  EXPECT_FALSE(fit_hyperbola(kNGrenz, kAKonst, neg).has_value());
  EXPECT_FALSE(fit_hyperbola(0, kAKonst, two).has_value());
  EXPECT_FALSE(fit_hyperbola(kNGrenz, std::nan(""), two).has_value());
  // Points on a flat line make the hyperbola system singular (c = 1, u = w = 0).
  const std::array<CurvePoint, 2> flat{{{24000, 16000}, {36000, 16000}}};
  EXPECT_FALSE(fit_hyperbola(kNGrenz, kAKonst, flat).has_value());
}

TEST(AccelCurve, AsynchronousDriveSeedExample) {
  config::AccelCurve k;
  k.type = 3; k.a_max_deg_s2 = 16000; k.a_min_deg_s2 = 4000; k.n1_deg_s = 10000; k.n2_deg_s = 20000;
  EXPECT_DOUBLE_EQ(curve_accel_deg_s2(k, 0), 16000);
  EXPECT_DOUBLE_EQ(curve_accel_deg_s2(k, 10000), 16000);
  EXPECT_DOUBLE_EQ(curve_accel_deg_s2(k, 15000), 16000.0 * 10000 / 15000);
  EXPECT_DOUBLE_EQ(curve_accel_deg_s2(k, 20000), 8000);
  EXPECT_DOUBLE_EQ(curve_accel_deg_s2(k, 25000), 16000.0 * 10000 * 20000 / (25000.0 * 25000));
  EXPECT_DOUBLE_EQ(curve_accel_deg_s2(k, 40000), 4000);   // 16000*2e8/1.6e9 = 2000 -> a_min
  EXPECT_DOUBLE_EQ(curve_accel_deg_s2(k, -15000), curve_accel_deg_s2(k, 15000));
}

TEST(AccelCurve, MinimumAndNoCurve) {
  auto k = polynomial_curve({-0.88888888, 2.08333333E-5, -1.92901234E-10}, 3000);
  EXPECT_DOUBLE_EQ(curve_accel_deg_s2(k, 48000), 3000);  // 2000 from the table, floored at a_min
  EXPECT_DOUBLE_EQ(curve_accel_deg_s2(k, 11999.9), 16000);
  config::AccelCurve none;
  EXPECT_DOUBLE_EQ(curve_accel_deg_s2(none, 30000, 1234), 1234);
  config::AccelCurve broken; broken.type = 1;  // n_grenz 0
  EXPECT_DOUBLE_EQ(curve_accel_deg_s2(broken, 30000, 777), 777);
  EXPECT_DOUBLE_EQ(curve_accel_deg_s2(k, std::nan(""), 55), 55);
}

}  // namespace
}  // namespace nck::spindle
