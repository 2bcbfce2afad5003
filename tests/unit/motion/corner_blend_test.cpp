// Circular fillets for corner blending, checked against the geometry done
// by hand (90-degree line corner) and by sampling (line into arc, arc to arc).
#include "nck/motion/corner_blend.hpp"
#include "corner_test_helpers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace nck::motion {
namespace {

using corner_test::arc;
using corner_test::line;
using corner_test::p3;
double distance_to(const Segment& s, const AxisVector& q) { return corner_test::distance_to(s, q, 4000); }

// The fillet's largest distance from the programmed path a+b.
double max_deviation(const CornerBlend& cb, const Segment& a, const Segment& b) {
  double worst = 0;
  AxisVector p{};
  for (int i = 0; i <= 100; ++i) {
    cb.corner.point_at(cb.corner.length() * i / 100.0, p);
    worst = std::max(worst, std::min(distance_to(a, p), distance_to(b, p)));
  }
  return worst;
}

void expect_joined(const CornerBlend& cb) {
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(cb.before.end_point()[k], cb.corner.start_point()[k], 1e-12);
    EXPECT_NEAR(cb.corner.end_point()[k], cb.after.start_point()[k], 1e-12);
  }
  // Tangent at both joints.
  AxisVector t0{}, t1{};
  cb.before.tangent_at(cb.before.length(), t0);
  cb.corner.tangent_at(0, t1);
  EXPECT_NEAR(std::hypot(t0[0] - t1[0], t0[1] - t1[1]), 0, 1e-6);
  cb.corner.tangent_at(cb.corner.length(), t0);
  cb.after.tangent_at(0, t1);
  EXPECT_NEAR(std::hypot(t0[0] - t1[0], t0[1] - t1[1]), 0, 1e-6);
}

TEST(CornerBlend, RightAngleOfLinesByHand) {
  const Segment a = line(p3(0, 0), p3(10, 0)), b = line(p3(10, 0), p3(10, 10));
  const auto cb = blend_corner(a, b, {0.05, 5, 5});
  ASSERT_TRUE(cb);
  // Deviation = r (sqrt 2 - 1) at a right angle: r = 0.05 / 0.41421 = 0.120711 mm.
  const double r = 0.05 / (std::sqrt(2.0) - 1);
  EXPECT_NEAR(cb->radius_mm, r, 1e-9);
  EXPECT_NEAR(cb->deviation_mm, 0.05, 1e-9);
  EXPECT_NEAR(cb->before.end_point()[0], 10 - r, 1e-9);
  EXPECT_NEAR(cb->after.start_point()[1], r, 1e-9);
  EXPECT_NEAR(cb->corner.center_a(), 10 - r, 1e-9);
  EXPECT_NEAR(cb->corner.center_b(), r, 1e-9);
  EXPECT_NEAR(cb->corner.sweep_rad(), M_PI / 2, 1e-9);  // left turn: ccw
  EXPECT_NEAR(cb->corner.length(), r * M_PI / 2, 1e-9);
  EXPECT_NEAR(cb->shortfall_mm, r * (2 - M_PI / 2), 1e-9);  // 0.051802 mm
  EXPECT_NEAR(cb->after.end_point()[1], 10, 0);  // the block's end stays as programmed
  expect_joined(*cb);
  EXPECT_LE(max_deviation(*cb, a, b), 0.05 + 1e-6);
}

TEST(CornerBlend, TrimLimitCapsTheRadius) {
  const Segment a = line(p3(0, 0), p3(10, 0)), b = line(p3(10, 0), p3(10, -10));
  const auto cb = blend_corner(a, b, {1.0, 0.1, 5});  // at most 0.1 mm off a
  ASSERT_TRUE(cb);
  EXPECT_NEAR(cb->radius_mm, 0.1, 1e-9);
  EXPECT_NEAR(cb->deviation_mm, 0.1 * (std::sqrt(2.0) - 1), 1e-9);
  EXPECT_LT(cb->corner.sweep_rad(), 0);  // right turn: cw
  expect_joined(*cb);
}

// The common benchmark program's corner: a chord runs straight at the
// centre of a small semicircle (G2) and turns 90 degrees onto it.
TEST(CornerBlend, LineIntoSemicircleTouchesItFromOutside) {
  const double R = 0.25;
  const Segment a = line(p3(-0.5, 0), p3(0, 0)), b = arc(p3(0, 0), p3(2 * R, 0), R, 0, false);
  const auto cb = blend_corner(a, b, {0.01, 0.225, 0.45 * b.length()});
  ASSERT_TRUE(cb);
  const double r = cb->radius_mm, fx = cb->corner.center_a(), fy = cb->corner.center_b();
  EXPECT_NEAR(fy, r, 1e-9);                             // tangent to the line y = 0
  EXPECT_NEAR(std::hypot(fx - R, fy), R + r, 1e-9);     // tangent to the circle from outside
  EXPECT_NEAR(std::hypot(fx, fy) - r, 0.01, 1e-9);      // PATH_DEV used up
  // The trimmed semicircle keeps its centre and radius.
  EXPECT_EQ(cb->after.kind(), SegmentKind::arc);
  EXPECT_NEAR(cb->after.center_a(), R, 1e-12);
  EXPECT_NEAR(cb->after.radius_start(), R, 1e-9);
  expect_joined(*cb);
  EXPECT_LE(max_deviation(*cb, a, b), 0.01 + 1e-6);
  EXPECT_GT(cb->shortfall_mm, 0);
  EXPECT_LT(cb->shortfall_mm, 2 * 0.01);  // the documented bound per corner
}

TEST(CornerBlend, ArcToArcStaysWithinTheDeviation) {
  // Two quarter circles meeting at a right angle.
  const Segment a = arc(p3(0, 0), p3(5, 5), 5, 0, false);   // cw, at (5,5) heading +X
  const Segment b = arc(p3(5, 5), p3(10, 0), 5, 0, false);  // continues: tangent, no corner
  EXPECT_FALSE(blend_corner(a, b, {0.02, 1, 1}));            // tangent: nothing to blend
  const Segment c = arc(p3(5, 5), p3(10, 0), 10, 5, true);  // ccw, heading -Y: a right turn
  const auto cb = blend_corner(a, c, {0.02, 1, 1});
  ASSERT_TRUE(cb);
  expect_joined(*cb);
  EXPECT_NEAR(cb->deviation_mm, 0.02, 1e-9);
  EXPECT_LE(max_deviation(*cb, a, c), 0.02 + 1e-6);
}

TEST(CornerBlend, NoFilletWhereNoneBelongs) {
  const Segment a = line(p3(0, 0), p3(10, 0));
  EXPECT_FALSE(blend_corner(a, line(p3(10, 0), p3(20, 0)), {0.05, 5, 5}));   // collinear
  EXPECT_FALSE(blend_corner(a, line(p3(10, 0), p3(0, 0)), {0.05, 5, 5}));    // reversal
  EXPECT_FALSE(blend_corner(a, line(p3(10, 0), p3(10, 5, 5)), {0.05, 5, 5})); // corner in space
  EXPECT_FALSE(blend_corner(a, line(p3(10, 0), p3(10, 10)), {0.0, 5, 5}));   // no tolerance
  EXPECT_FALSE(blend_corner(a, line(p3(10, 0), p3(10, 10)), {0.05, 0, 5}));  // nothing may be trimmed
  // A helix after the corner: its Z moves.
  const Segment helix = *make_arc_center(p3(10, 0), p3(10, 10, 2), 3, 0, 1, 10, 5, true);
  EXPECT_FALSE(blend_corner(a, helix, {0.05, 5, 5}));
}

// Two ccw arcs with a gentle right kink (from a random program that broke
// the blend): every radius fits, the fillet tends to the arcs' common
// tangent. The radius stops at 10 m, where the fillet is still computed
// exactly (an unbounded search gave 7e14 mm and set points 0.1 mm off).
TEST(CornerBlend, GentleKinkBetweenArcsKeepsAFiniteExactFillet) {
  const Segment a = arc(p3(-9.634, 9.988), p3(20.840, 22.069), 5.603, 16.0285, true);
  const Segment b = arc(p3(20.840, 22.069), p3(-29.138, 8.678), -4.149, 15.3735, true);
  const auto cb = blend_corner(a, b, {0.05, 0.45 * a.length(), 0.45 * b.length()});
  ASSERT_TRUE(cb);
  EXPECT_LE(cb->radius_mm, 1e4);
  EXPECT_GT(cb->radius_mm, 1e3);
  expect_joined(*cb);
  AxisVector p{};
  cb->corner.point_at(0.001, p);
  EXPECT_NEAR(std::hypot(p[0] - cb->corner.start_point()[0], p[1] - cb->corner.start_point()[1]), 0.001, 1e-6);
  EXPECT_LE(max_deviation(*cb, a, b), 0.05 + 1e-6);
}

}  // namespace
}  // namespace nck::motion
