// The spindle's jerk-limited ramps (getriebe[i].slope_type, P-AXIS-00270:
// 1 TRAPEZ, 2 SIN2) against their closed form: a run-up from rest to v
// with acceleration a and the ramp times tr_zu (build-up) and tr_ab
// (reduction) takes v/a + (tr_zu + tr_ab)/2 when it reaches a, and
// a_p (tr_zu + tr_ab)/a with a_p = sqrt(2 v a / (tr_zu + tr_ab)) when it
// does not (a sin^2 ramp gains the same speed as a straight one). Times
// within 1 % or one cycle; every cycle's finite-difference jerk within
// a/tr (TRAPEZ) or (pi/2) a/tr (SIN2) of the ramp in force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "spindle_test_util.hpp"

namespace nck::spindle {
namespace {

constexpr double kDt = 0.001;

// a_beschl 3000, a_brems 4000 deg/s^2 (spindle_axis_config), four
// different ramp times.
config::AxisConfig slope_config(SlopeProfile slope) {
  auto ax = test::spindle_axis_config();
  for (auto& g : ax.gears) {
    g.slope_type = slope;
    g.tr_acc_up_s = 0.080;   // tr_beschl_zu
    g.tr_acc_down_s = 0.050;  // tr_beschl_ab
    g.tr_dec_up_s = 0.060;   // tr_brems_zu
    g.tr_dec_down_s = 0.040;  // tr_brems_ab
  }
  return ax;
}

double shape(SlopeProfile p) { return p == SlopeProfile::sin2 ? std::numbers::pi / 2 : 1.0; }

// Set speeds (deg/s) cycle by cycle, and what they say about a and jerk.
struct Trace {
  std::vector<double> v{0.0, 0.0};  // at rest before
  void add(const SpindleAxis& s) { v.push_back(rpm_to_deg_s(s.status().set_rpm)); }
  double max_accel() const {
    double m = 0;
    for (std::size_t i = 1; i < v.size(); ++i) m = std::max(m, std::fabs(v[i] - v[i - 1]) / kDt);
    return m;
  }
  double max_jerk() const {
    double m = 0;
    for (std::size_t i = 2; i < v.size(); ++i) m = std::max(m, std::fabs(v[i] - 2 * v[i - 1] + v[i - 2]) / (kDt * kDt));
    return m;
  }
};

// Ticks until the set speed equals rpm exactly; returns the cycles taken.
int ramp_cycles(SpindleAxis& s, double rpm, Trace& tr, int max = 100000) {
  for (int i = 1; i <= max; ++i) {
    s.tick(kDt);
    tr.add(s);
    if (s.status().set_rpm == rpm) return i;
  }
  return max;
}

void expect_time(int cycles, double t_s) {
  const double want = t_s / kDt;
  EXPECT_LE(std::fabs(cycles - want), std::max(0.01 * want, 1.0)) << cycles << " cycles against " << t_s << " s";
}

class SpindleSlope : public ::testing::TestWithParam<SlopeProfile> {};

TEST_P(SpindleSlope, RunUpAndStopTakeTheClosedFormTimeWithinTheJerk) {
  const SlopeProfile p = GetParam();
  auto s = test::make_spindle(slope_config(p), kDt);
  ASSERT_TRUE(s.rotate(1000).ok());  // 6000 deg/s
  Trace up;
  expect_time(ramp_cycles(s, 1000, up), 6000.0 / 3000 + (0.080 + 0.050) / 2);  // 2.065 s
  EXPECT_LE(up.max_accel(), 3000 * (1 + 1e-9));
  EXPECT_GT(up.max_accel(), 3000 * 0.999);  // reaches a_beschl
  // The build-up is the steeper of the two acceleration ramps.
  EXPECT_LE(up.max_jerk(), shape(p) * 3000 / 0.050 * (1 + 1e-6));
  EXPECT_GT(up.max_jerk(), shape(p) * 3000 / 0.050 * 0.9);
  ASSERT_TRUE(s.stop().ok());
  Trace down{{rpm_to_deg_s(1000), rpm_to_deg_s(1000)}};
  expect_time(ramp_cycles(s, 0, down), 6000.0 / 4000 + (0.060 + 0.040) / 2);  // 1.55 s
  EXPECT_LE(down.max_accel(), 4000 * (1 + 1e-9));
  EXPECT_LE(down.max_jerk(), shape(p) * 4000 / 0.040 * (1 + 1e-6));
  s.tick(kDt);
  EXPECT_EQ(s.status().set_accel_deg_s2, 0);  // at rest, nothing more planned
  EXPECT_EQ(s.status().set_rpm, 0);
}

TEST_P(SpindleSlope, ShortChangeStaysBelowTheAcceleration) {
  const SlopeProfile p = GetParam();
  auto s = test::make_spindle(slope_config(p), kDt);
  ASSERT_TRUE(s.rotate(10).ok());  // 60 deg/s: below a (tr_zu + tr_ab) / 2 = 195 deg/s
  Trace up;
  const double a_peak = std::sqrt(2 * 60.0 * 3000 / 0.130);  // 1664 deg/s^2
  expect_time(ramp_cycles(s, 10, up), a_peak * 0.130 / 3000);  // 72 ms
  EXPECT_LE(up.max_accel(), a_peak * (1 + 1e-6));
  EXPECT_LE(up.max_jerk(), shape(p) * 3000 / 0.050 * (1 + 1e-6));
}

TEST_P(SpindleSlope, OverrideAndReversalKeepTheJerk) {
  const SlopeProfile p = GetParam();
  auto s = test::make_spindle(slope_config(p), kDt);
  const double j_max = shape(p) * std::max(3000 / 0.050, 4000 / 0.040) * (1 + 1e-6);
  Trace tr;
  ASSERT_TRUE(s.rotate(500).ok());
  for (int i = 0; i < 300; ++i) {  // mid-ramp changes replan from the state reached
    s.tick(kDt);
    tr.add(s);
    if (i == 100) s.set_override_pct(150);
    if (i == 200) s.set_feedhold(true);
  }
  s.set_feedhold(false);
  ASSERT_TRUE(s.rotate(-800).ok());  // M4: through standstill
  int zero_crossings = 0;
  for (int i = 0; i < 4000; ++i) {
    s.tick(kDt);
    tr.add(s);
    const std::size_t n = tr.v.size();
    if ((tr.v[n - 2] > 0 && tr.v[n - 1] < 0)) ++zero_crossings;
  }
  EXPECT_EQ(s.status().set_rpm, -800 * 1.5);  // at the new speed, override 150 %
  EXPECT_EQ(zero_crossings, 0);  // it stops at 0 before it turns the other way
  EXPECT_LE(tr.max_accel(), 4000 * (1 + 1e-9));
  EXPECT_LE(tr.max_jerk(), j_max);
}

// M19 from standstill (no automatic homing: kenngr.achs_mode 0x100) over
// 170 deg at 100 rpm (600 deg/s), tr_zu = tr_ab per side so that the mean
// speed of each ramp is v/2: t = L/v + (v/a_b + tr_b)/2 + (v/a_br + tr_br)/2.
TEST_P(SpindleSlope, M19LandsExactlyInTheClosedFormTime) {
  const SlopeProfile p = GetParam();
  auto ax = slope_config(p);
  ax.axis_mode |= 0x100;
  for (auto& g : ax.gears) g.tr_acc_up_s = g.tr_acc_down_s = 0.050, g.tr_dec_up_s = g.tr_dec_down_s = 0.040;
  auto s = test::make_spindle(ax, kDt);
  ASSERT_TRUE(s.position(170, Direction::none, 100).ok());
  Trace tr;
  int cycles = 0;
  double max_step = 0;
  for (; cycles < 5000 && !s.status().in_position; ++cycles) {
    const double before = s.status().distance_to_go_deg, pos_before = s.status().set_pos_deg;
    s.tick(kDt);
    tr.add(s);
    if (cycles > 0) {
      EXPECT_LE(s.status().distance_to_go_deg, before + 1e-12);  // never overshoots
    }
    EXPECT_GE(s.status().distance_to_go_deg, 0);
    max_step = std::max(max_step, std::fabs(s.status().set_pos_deg - pos_before));
  }
  ASSERT_TRUE(s.status().in_position);
  EXPECT_NEAR(s.status().set_pos_deg, 170, 1e-9);
  const double t = 170.0 / 600 + (600.0 / 3000 + 0.050) / 2 + (600.0 / 4000 + 0.040) / 2;  // 0.5033 s
  // in_position comes the cycle after the set point lands (the drive follows).
  expect_time(cycles - 1, t);
  EXPECT_LE(tr.max_accel(), 4000 * (1 + 1e-9));
  EXPECT_LE(tr.max_jerk(), shape(p) * 4000 / 0.040 * (1 + 1e-6));
  EXPECT_LE(max_step, 600 * kDt * (1 + 1e-9));
}

INSTANTIATE_TEST_SUITE_P(Profiles, SpindleSlope, ::testing::Values(SlopeProfile::trapez, SlopeProfile::sin2),
                         [](const ::testing::TestParamInfo<SlopeProfile>& p) { return std::string(slope_name(p.param)); });

// STEP (slope_type 0) keeps its acceleration steps: the run-up takes v/a.
TEST(SpindleSlopeStep, StepIsUnchanged) {
  auto s = test::make_spindle(slope_config(SlopeProfile::step), kDt);
  ASSERT_TRUE(s.rotate(1000).ok());
  Trace up;
  EXPECT_EQ(ramp_cycles(s, 1000, up), 2000);
  EXPECT_GT(up.max_jerk(), 3000 / kDt * 0.99);  // a step in one cycle
}

// With a curve the config layer makes the stage STEP (930900); the
// interpolator then takes the curve's a(n) as before.
TEST(SpindleSlopeStep, GearStagesKeepTheirOwnProfile) {
  auto ax = slope_config(SlopeProfile::trapez);
  ax.gears[1].slope_type = SlopeProfile::step;
  auto s = test::make_spindle(ax, kDt);
  EXPECT_EQ(s.config().gears[0].slope, SlopeProfile::trapez);
  EXPECT_EQ(s.config().gears[1].slope, SlopeProfile::step);
  EXPECT_DOUBLE_EQ(s.config().gears[0].ramp_times.acc_up_s, 0.080);
  EXPECT_DOUBLE_EQ(s.config().gears[0].ramp_times.dec_down_s, 0.040);
  ASSERT_TRUE(s.load_gear_data(2).ok());
  ASSERT_TRUE(s.rotate(1000).ok());
  Trace up;
  EXPECT_EQ(ramp_cycles(s, 1000, up), 2000);
}

}  // namespace
}  // namespace nck::spindle
