// The parabolic corner blend (SegmentKind::parabola, issue 30): its
// geometry against the closed form at a right angle between lines, the
// constant axis acceleration of its parametrisation, and the joints of a
// line-arc and an arc-line corner (tangent, on the circle, within PATH_DEV).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "nck/motion/corner_blend.hpp"
#include "corner_test_helpers.hpp"

namespace nck::motion {
namespace {

using corner_test::arc;
using corner_test::line;
using corner_test::p3;
double distance_to(const Segment& s, const AxisVector& q) { return corner_test::distance_to(s, q, 20000); }

double unit_gap(const AxisVector& a, const AxisVector& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// Both joints continuous in position and in the unit tangent (the path
// speed passes on unchanged because the parabola's legs are equal).
void expect_joined(const CornerBlend& cb) {
  EXPECT_LT(unit_gap(cb.before.end_point(), cb.corner.start_point()), 1e-12);
  EXPECT_LT(unit_gap(cb.corner.end_point(), cb.after.start_point()), 1e-12);
  AxisVector t0{}, t1{};
  cb.before.tangent_at(cb.before.length(), t0);
  cb.corner.tangent_at(0, t1);
  EXPECT_LT(unit_gap(t0, t1), 1e-9);
  cb.corner.tangent_at(cb.corner.length(), t0);
  cb.after.tangent_at(0, t1);
  EXPECT_LT(unit_gap(t0, t1), 1e-9);
}

TEST(CornerParabola, RightAngleBetweenLinesHasTheClosedForm) {
  const Segment a = line(p3(0, 0), p3(1, 0)), b = line(p3(1, 0), p3(1, 1));
  const auto cb = blend_corner_parabola(a, b, {0.01, 0.45, 0.45});
  ASSERT_TRUE(cb);
  ASSERT_EQ(cb->corner.kind(), SegmentKind::parabola);
  // leg = 4 PATH_DEV / |t_out - t_in| = 0.04 / sqrt 2; the control point is the corner.
  const double leg = 0.04 / std::sqrt(2.0);
  EXPECT_NEAR(cb->radius_mm, leg, 1e-9);
  EXPECT_NEAR(cb->corner.length(), 2 * leg, 1e-9);
  EXPECT_NEAR(cb->corner.control_a(), 1, 1e-12);
  EXPECT_NEAR(cb->corner.control_b(), 0, 1e-12);
  EXPECT_NEAR(cb->before.end_point()[0], 1 - leg, 1e-9);
  EXPECT_NEAR(cb->after.start_point()[1], leg, 1e-9);
  // Its middle (p0 + 2 c + p2) / 4 is PATH_DEV from the corner, and nothing is closer.
  AxisVector mid{};
  cb->corner.point_at(leg, mid);
  EXPECT_NEAR(mid[0], 1 - leg / 4, 1e-9);
  EXPECT_NEAR(mid[1], leg / 4, 1e-9);
  EXPECT_NEAR(cb->deviation_mm, 0.01, 1e-9);
  EXPECT_NEAR(distance_to(cb->corner, p3(1, 0)), 0.01, 1e-9);
  expect_joined(*cb);
  // Cut: both trims less the curve's length (below 2 x PATH_DEV).
  EXPECT_GT(cb->shortfall_mm, 0);
  EXPECT_LT(cb->shortfall_mm, 0.02);
}

// Stepping s uniformly, every axis's second difference is the same: the
// axes accelerate constantly, X braking to 0 while Y speeds up from 0.
TEST(CornerParabola, UniformPathSpeedGivesEveryAxisAConstantAcceleration) {
  const Segment a = line(p3(0, 0), p3(1, 0)), b = line(p3(1, 0), p3(1, 1));
  const auto cb = blend_corner_parabola(a, b, {0.01, 0.45, 0.45});
  ASSERT_TRUE(cb);
  const Segment& z = cb->corner;
  const double h = z.length() / 40, len2 = z.length() * z.length();
  // 2 (p0 - 2 c + p2) / length^2 per (mm of s)^2: X -leg, Y +leg.
  const double ax = 2 * (z.start_point()[0] - 2 * z.control_a() + z.end_point()[0]) / len2;
  const double ay = 2 * (z.start_point()[1] - 2 * z.control_b() + z.end_point()[1]) / len2;
  EXPECT_NEAR(ax, -ay, 1e-9);
  AxisVector p0{}, p1{}, p2{};
  for (int i = 1; i < 40; ++i) {
    z.point_at((i - 1) * h, p0);
    z.point_at(i * h, p1);
    z.point_at((i + 1) * h, p2);
    EXPECT_NEAR((p2[0] - 2 * p1[0] + p0[0]) / (h * h), ax, 1e-4 * std::fabs(ax));
    EXPECT_NEAR((p2[1] - 2 * p1[1] + p0[1]) / (h * h), ay, 1e-4 * std::fabs(ay));
  }
  // The tangent is the axes' share of the path speed: unit at both ends,
  // cos 45 degrees in the middle.
  AxisVector t{};
  z.tangent_at(0, t);
  EXPECT_NEAR(std::hypot(t[0], t[1]), 1, 1e-12);
  z.tangent_at(z.length() / 2, t);
  EXPECT_NEAR(std::hypot(t[0], t[1]), std::sqrt(0.5), 1e-12);
}

// The common program's corner: a chord into a small semicircle at a right
// angle (G2, r 0.25 mm) and out of it again.
TEST(CornerParabola, LineArcAndArcLineAreTangentOnTheCircleAndWithinPathDev) {
  const Segment chord = line(p3(0, 0), p3(2, 0));
  const Segment semi = arc(p3(2, 0), p3(2.5, 0), 2.25, 0, false);
  const Segment next = line(p3(2.5, 0), p3(4.5, 0));
  for (const auto& [a, b] : {std::pair{chord, semi}, std::pair{semi, next}}) {
    const auto cb = blend_corner_parabola(a, b, {0.01, 0.45 * a.length(), 0.45 * b.length()});
    ASSERT_TRUE(cb);
    EXPECT_EQ(cb->corner.kind(), SegmentKind::parabola);
    expect_joined(*cb);
    const AxisVector corner = a.end_point();
    EXPECT_NEAR(cb->deviation_mm, 0.01, 1e-6);
    EXPECT_NEAR(distance_to(cb->corner, corner), cb->deviation_mm, 1e-6);
    // The end on the arc lies on its circle.
    const AxisVector& on_arc = a.kind() == SegmentKind::arc ? cb->corner.start_point() : cb->corner.end_point();
    EXPECT_NEAR(std::hypot(on_arc[0] - 2.25, on_arc[1]), 0.25, 1e-12);
    // Equal legs: unit tangent at both ends.
    AxisVector t{};
    cb->corner.tangent_at(0, t);
    EXPECT_NEAR(std::hypot(t[0], t[1]), 1, 1e-9);
    cb->corner.tangent_at(cb->corner.length(), t);
    EXPECT_NEAR(std::hypot(t[0], t[1]), 1, 1e-9);
  }
}

TEST(CornerParabola, RemainderIsTheSameCurveAndSpeedLaw) {
  const Segment a = line(p3(0, 0, 1), p3(1, 0, 1)), b = line(p3(1, 0, 1), p3(1.5, 0.8, 1));
  const auto cb = blend_corner_parabola(a, b, {0.02, 0.45, 0.45});
  ASSERT_TRUE(cb);
  const double s0 = 0.3 * cb->corner.length();
  const Segment rest = cb->corner.remainder(s0);
  EXPECT_NEAR(rest.length(), cb->corner.length() - s0, 1e-12);
  EXPECT_EQ(rest.plane_arc_length(), rest.length());
  AxisVector p{}, q{};
  for (int i = 0; i <= 10; ++i) {
    const double s = rest.length() * i / 10;
    rest.point_at(s, p);
    cb->corner.point_at(s0 + s, q);
    EXPECT_LT(unit_gap(p, q), 1e-12);
    EXPECT_EQ(p[2], 1);
  }
}

// The command queue carries a motion without its start (SegmentTail):
// joined again it is the same parabola, bit for bit.
TEST(CornerParabola, TailAndJoinedKeepItBitForBit) {
  const Segment a = line(p3(0, 0), p3(1, 0)), b = line(p3(1, 0), p3(1, 1));
  const auto cb = blend_corner_parabola(a, b, {0.01, 0.45, 0.45});
  ASSERT_TRUE(cb);
  const Segment back = Segment::joined(cb->corner.start_point(), cb->corner.tail());
  EXPECT_EQ(back.kind(), SegmentKind::parabola);
  AxisVector p{}, q{};
  for (int i = 0; i <= 10; ++i) {
    back.point_at(cb->corner.length() * i / 10, p);
    cb->corner.point_at(cb->corner.length() * i / 10, q);
    EXPECT_EQ(p, q);
  }
}

TEST(CornerParabola, NoneBetweenTwoArcsOrAtAReversal) {
  const Segment a1 = arc(p3(0, 0), p3(1, 1), 1, 0, true), a2 = arc(p3(1, 1), p3(2, 0), 1, 0, true);
  EXPECT_FALSE(blend_corner_parabola(a1, arc(p3(1, 1), p3(0, 2), 0, 1, false), {0.01, 0.5, 0.5}));
  (void)a2;
  const Segment there = line(p3(0, 0), p3(1, 0)), back = line(p3(1, 0), p3(0, 0));
  EXPECT_FALSE(blend_corner_parabola(there, back, {0.01, 0.45, 0.45}));
}

}  // namespace
}  // namespace nck::motion
