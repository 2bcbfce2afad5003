// Path limits from axis limits: lines at angles, arcs with centripetal limit.
#include "nck/motion/limits.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "nck/motion/jerk_profile.hpp"

namespace nck::motion {
namespace {

constexpr double kSqrt2 = std::numbers::sqrt2;

AxisVector pt(double x, double y, double z = 0.0) {
  AxisVector v{};
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

TEST(PathLimits, SingleAxisLineTakesThatAxis) {
  const std::array<AxisDynamics, 2> ax{{{100, 1000, 2000}, {10, 10, 10}}};
  auto seg = make_line(pt(0, 0), pt(50, 0), 2);
  ASSERT_TRUE(seg);
  const PathLimits l = path_limits(*seg, ax);
  EXPECT_DOUBLE_EQ(l.v_max_mm_s, 100.0);  // Y does not move: its low limits do not count
  EXPECT_DOUBLE_EQ(l.a_acc_mm_s2, 1000.0);
  EXPECT_DOUBLE_EQ(l.a_dec_mm_s2, 2000.0);
}

TEST(PathLimits, Line45DegreesEqualAxes) {
  const std::array<AxisDynamics, 2> ax{{{100, 1000, 1000}, {100, 1000, 1000}}};
  auto seg = make_line(pt(0, 0), pt(10, 10), 2);
  ASSERT_TRUE(seg);
  const PathLimits l = path_limits(*seg, ax);
  EXPECT_NEAR(l.v_max_mm_s, 100.0 * kSqrt2, 1e-9);
  EXPECT_NEAR(l.a_acc_mm_s2, 1000.0 * kSqrt2, 1e-9);
}

TEST(PathLimits, Line45DegreesSlowAxisDominates) {
  const std::array<AxisDynamics, 2> ax{{{100, 1000, 800}, {50, 2000, 300}}};
  auto seg = make_line(pt(0, 0), pt(-10, 10), 2);
  ASSERT_TRUE(seg);
  const PathLimits l = path_limits(*seg, ax);
  EXPECT_NEAR(l.v_max_mm_s, 50.0 * kSqrt2, 1e-9);
  EXPECT_NEAR(l.a_acc_mm_s2, 1000.0 * kSqrt2, 1e-9);
  EXPECT_NEAR(l.a_dec_mm_s2, 300.0 * kSqrt2, 1e-9);
}

TEST(PathLimits, Line3_4_12) {
  // Direction (3,4,12)/13: Z is the limiting axis for equal limits.
  const std::array<AxisDynamics, 3> ax{{{100, 100, 100}, {100, 100, 100}, {100, 100, 100}}};
  auto seg = make_line(pt(0, 0, 0), pt(3, 4, 12), 3);
  ASSERT_TRUE(seg);
  EXPECT_NEAR(path_limits(*seg, ax).v_max_mm_s, 100.0 * 13.0 / 12.0, 1e-9);
}

TEST(PathLimits, ArcCentripetal) {
  // r = 10, a = 1000: v <= sqrt(1000 * 10 / sqrt2) = 84.09 mm/s; tangential a/sqrt2.
  const std::array<AxisDynamics, 2> ax{{{1000, 1000, 1000}, {1000, 1000, 1000}}};
  auto seg = make_arc_center(pt(10, 0), pt(0, 10), 2, 0, 1, 0, 0, true);
  ASSERT_TRUE(seg);
  const PathLimits l = path_limits(*seg, ax);
  EXPECT_NEAR(l.v_max_mm_s, std::sqrt(10000.0 / kSqrt2), 1e-9);
  EXPECT_NEAR(l.v_max_mm_s, 84.0896, 1e-4);
  EXPECT_NEAR(l.a_acc_mm_s2, 1000.0 / kSqrt2, 1e-9);
}

// A small arc under TRAPEZ (common program's semicircles: r = 0.25 mm, a
// 2,500 mm/s^2, 50 ms ramps): its turn holds speed and tangential
// acceleration down (v^3/r^2 and 3 v a_t / r each within j_geom, 0.259 of
// a/tr, so that the jerk's length (j_t - v^3/r^2, 3 v a_t / r) stays
// within a/tr), but the path's own jerk keeps a / sqrt2 / tr: the ramps of
// the smaller acceleration are shorter. With the full ramp time and the
// three terms summed, the arc ramped at 1,584 mm/s^3 and took 0.254 s.
TEST(PathLimits, SmallArcUnderTrapezKeepsThePathsJerk) {
  const RampTimes tr{0.05, 0.05, 0.05, 0.05};
  const std::array<AxisDynamics, 2> ax{{{500, 2500, 2500, tr}, {500, 2500, 2500, tr}}};
  auto seg = make_arc_center(pt(0, 0), pt(0, 0.5), 2, 0, 1, 0, 0.25, false);
  ASSERT_TRUE(seg);
  const PathLimits l = path_limits(*seg, ax, SlopeProfile::trapez);
  const double j_axis = 2500 / 0.05, j_geom = (std::sqrt(6.0) - kSqrt2) / 4 * j_axis;  // 12,941 mm/s^3
  EXPECT_NEAR(std::hypot(j_axis / kSqrt2 + j_geom, j_geom), j_axis, 1e-6);
  const double v_arc = std::cbrt(j_geom * 0.25 * 0.25);
  EXPECT_NEAR(l.v_max_mm_s, v_arc, 1e-9);
  EXPECT_NEAR(l.v_max_mm_s, 9.3171, 1e-4);
  EXPECT_NEAR(l.a_acc_mm_s2, j_geom * 0.25 / (3 * v_arc), 1e-9);
  EXPECT_NEAR(l.a_acc_mm_s2, 115.745, 1e-3);
  const JerkLimits j = jerk_limits(l);
  for (const double t : {j.tr_acc_up_s, j.tr_acc_down_s})
    EXPECT_NEAR(l.a_acc_mm_s2 / t, 2500 / kSqrt2 / 0.05, 1e-6);  // 35,355 mm/s^3, as on a line
  for (const double t : {j.tr_dec_up_s, j.tr_dec_down_s}) EXPECT_NEAR(l.a_dec_mm_s2 / t, 2500 / kSqrt2 / 0.05, 1e-6);
  // A large arc keeps its ramp times (nothing holds its acceleration down).
  auto big = make_arc_center(pt(0, 0), pt(0, 2000), 2, 0, 1, 0, 1000, false);
  ASSERT_TRUE(big);
  EXPECT_EQ(path_limits(*big, ax, SlopeProfile::trapez).tr, tr);
  // So does a helix whose slow third axis binds the path's acceleration
  // (its own jerk stays a / tr).
  const std::array<AxisDynamics, 3> slow_z{{ax[0], ax[1], {500, 10, 10, tr}}};
  auto helix = make_arc_center(pt(0, 0, 0), pt(0, 0.5, 0.5), 3, 0, 1, 0, 0.25, false);
  ASSERT_TRUE(helix);
  const PathLimits h = path_limits(*helix, slow_z, SlopeProfile::trapez);
  EXPECT_LT(h.a_acc_mm_s2, 79.0);
  EXPECT_EQ(h.tr, tr);
}

TEST(PathLimits, ArcBigRadiusTakesSlowerPlaneAxis) {
  const std::array<AxisDynamics, 2> ax{{{200, 5000, 4000}, {100, 3000, 6000}}};
  auto seg = make_arc_center(pt(1000, 0), pt(0, 1000), 2, 0, 1, 0, 0, false);
  ASSERT_TRUE(seg);
  const PathLimits l = path_limits(*seg, ax);
  EXPECT_DOUBLE_EQ(l.v_max_mm_s, 100.0);  // centripetal allows ~1682 mm/s
  EXPECT_NEAR(l.a_acc_mm_s2, 3000.0 / kSqrt2, 1e-9);
  EXPECT_NEAR(l.a_dec_mm_s2, 4000.0 / kSqrt2, 1e-9);
}

TEST(PathLimits, HelixTrackingAxis) {
  // Full circle r=10 (arc 62.83) with Z lead 62.83: Z share 1/sqrt2 limits v.
  const double arc = 20.0 * std::numbers::pi;
  const std::array<AxisDynamics, 3> ax{{{1000, 1e6, 1e6}, {1000, 1e6, 1e6}, {10, 100, 100}}};
  auto seg = make_arc_center(pt(10, 0, 0), pt(10, 0, arc), 3, 0, 1, 0, 0, true);
  ASSERT_TRUE(seg);
  const PathLimits l = path_limits(*seg, ax);
  EXPECT_NEAR(l.v_max_mm_s, 10.0 * kSqrt2, 1e-9);
  EXPECT_NEAR(l.a_acc_mm_s2, 100.0 * kSqrt2, 1e-9);
}

TEST(PathLimits, StandstillAndValidity) {
  const std::array<AxisDynamics, 2> ax{{{100, 1000, 2000}, {50, 3000, 700}}};
  auto seg = make_line(pt(1, 1), pt(1, 1), 2);
  ASSERT_TRUE(seg);
  const PathLimits l = path_limits(*seg, ax);
  EXPECT_DOUBLE_EQ(l.v_max_mm_s, 50.0);
  EXPECT_DOUBLE_EQ(l.a_dec_mm_s2, 700.0);
  EXPECT_TRUE(valid(l));
  EXPECT_FALSE(valid(PathLimits{}));
  EXPECT_FALSE(valid(PathLimits{std::numeric_limits<double>::infinity(), 1, 1}));
  EXPECT_FALSE(valid(PathLimits{1, NAN, 1}));
  // No dynamics given for the moving axes: nothing limits, so not valid.
  auto moving = make_line(pt(0, 0), pt(1, 0), 2);
  EXPECT_FALSE(valid(path_limits(*moving, std::span<const AxisDynamics>{})));
}

}  // namespace
}  // namespace nck::motion
