// Geometry of lines, arcs and helices, checked against hand-computed values.
#include "nck/motion/segment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace nck::motion {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::size_t X = 0, Y = 1, Z = 2, A = 3;

AxisVector pt(double x, double y, double z = 0.0, double a = 0.0) {
  AxisVector v{};
  v[X] = x;
  v[Y] = y;
  v[Z] = z;
  v[A] = a;
  return v;
}

TEST(SegmentLine, LengthAndMidpoint) {
  auto seg = make_line(pt(0, 0, 0), pt(3, 4, 12), 3);
  ASSERT_TRUE(seg);
  EXPECT_DOUBLE_EQ(seg->length(), 13.0);
  AxisVector p{};
  seg->point_at(6.5, p);
  EXPECT_DOUBLE_EQ(p[X], 1.5);
  EXPECT_DOUBLE_EQ(p[Y], 2.0);
  EXPECT_DOUBLE_EQ(p[Z], 6.0);
  AxisVector t{};
  seg->tangent_at(1.0, t);
  EXPECT_DOUBLE_EQ(t[X], 3.0 / 13.0);
  EXPECT_DOUBLE_EQ(t[Z], 12.0 / 13.0);
}

TEST(SegmentLine, EndIsExactAndSClamped) {
  const AxisVector a = pt(0.1, 0.2, 0.3), b = pt(10.7, -3.3, 1.0 / 3.0);
  auto seg = make_line(a, b, 3);
  ASSERT_TRUE(seg);
  AxisVector p{};
  seg->point_at(seg->length() * 2.0, p);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(p[i], b[i]);
  seg->point_at(-1.0, p);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(p[i], a[i]);
  seg->point_at(std::nan(""), p);
  EXPECT_EQ(p[X], a[X]);
}

TEST(SegmentLine, AxesBeyondCountUntouched) {
  auto seg = make_line(pt(0, 0, 0, 0), pt(1, 1, 1, 50), 2);
  ASSERT_TRUE(seg);
  EXPECT_DOUBLE_EQ(seg->length(), std::sqrt(2.0));
  AxisVector p{};
  p[Z] = 99.0;
  seg->point_at(seg->length(), p);
  EXPECT_EQ(p[Z], 99.0);
}

TEST(SegmentLine, LengthMaskLetsRotaryFollow) {
  // X moves 30 mm, A turns 90 deg: F refers to X only.
  auto seg = make_line(pt(0, 0, 0, 0), pt(30, 0, 0, 90), 4, 0b0111);
  ASSERT_TRUE(seg);
  EXPECT_DOUBLE_EQ(seg->length(), 30.0);
  AxisVector p{};
  seg->point_at(10.0, p);
  EXPECT_DOUBLE_EQ(p[A], 30.0);
  // Only the rotary axis moves: it counts after all.
  auto rot = make_line(pt(0, 0, 0, 0), pt(0, 0, 0, 90), 4, 0b0111);
  ASSERT_TRUE(rot);
  EXPECT_DOUBLE_EQ(rot->length(), 90.0);
}

TEST(SegmentLine, ZeroLengthAndErrors) {
  auto seg = make_line(pt(1, 2), pt(1, 2), 2);
  ASSERT_TRUE(seg);
  EXPECT_EQ(seg->length(), 0.0);
  AxisVector p{};
  seg->point_at(0.0, p);
  EXPECT_EQ(p[X], 1.0);
  EXPECT_EQ(make_line(pt(0, 0), pt(1, 1), 0).error(), ArcError::invalid_axis_count);
  EXPECT_EQ(make_line(pt(0, 0), pt(1, 1), 33).error(), ArcError::invalid_axis_count);
  EXPECT_EQ(make_line(pt(0, NAN), pt(1, 1), 2).error(), ArcError::non_finite_input);
  EXPECT_EQ(make_line(pt(0, 0), pt(INFINITY, 1), 2).error(), ArcError::non_finite_input);
}

// Quarter circle of radius 10 from (10,0) to (0,10) around the origin, in the
// plane (a, b); ccw from a towards b.
void expect_quarter(std::size_t a, std::size_t b) {
  AxisVector s{}, e{};
  s[a] = 10.0;
  e[b] = 10.0;
  auto seg = make_arc_center(s, e, 3, a, b, 0.0, 0.0, true);
  ASSERT_TRUE(seg);
  EXPECT_NEAR(seg->length(), 5.0 * kPi, 1e-12);
  EXPECT_NEAR(seg->sweep_rad(), kPi / 2.0, 1e-12);
  AxisVector p{};
  seg->point_at(seg->length() / 2.0, p);
  EXPECT_NEAR(p[a], 10.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(p[b], 10.0 / std::sqrt(2.0), 1e-12);
  // The third axis does not move.
  const std::size_t c = 3 - a - b;
  EXPECT_EQ(p[c], 0.0);
  AxisVector t{};
  seg->tangent_at(0.0, t);  // at (10, 0) ccw: straight towards +b
  EXPECT_NEAR(t[a], 0.0, 1e-12);
  EXPECT_NEAR(t[b], 1.0, 1e-12);

  // The same end points clockwise go the long way: three quarters.
  auto cw = make_arc_center(s, e, 3, a, b, 0.0, 0.0, false);
  ASSERT_TRUE(cw);
  EXPECT_NEAR(cw->length(), 15.0 * kPi, 1e-12);
  EXPECT_NEAR(cw->sweep_rad(), -1.5 * kPi, 1e-12);
  cw->point_at(cw->length() / 3.0, p);  // a quarter turn cw from (10,0): (0,-10)
  EXPECT_NEAR(p[a], 0.0, 1e-12);
  EXPECT_NEAR(p[b], -10.0, 1e-12);
}

TEST(SegmentArc, QuarterCircleG17) { expect_quarter(X, Y); }
TEST(SegmentArc, QuarterCircleG18) { expect_quarter(Z, X); }  // ZX plane, K/I
TEST(SegmentArc, QuarterCircleG19) { expect_quarter(Y, Z); }  // YZ plane, J/K

TEST(SegmentArc, OffsetCentreCwQuarter) {
  // G17 G02 from (20,10) to (10,0) around (10,10): cw quarter, radius 10.
  auto seg = make_arc_center(pt(20, 10), pt(10, 0), 2, X, Y, 10, 10, false);
  ASSERT_TRUE(seg);
  EXPECT_NEAR(seg->length(), 5.0 * kPi, 1e-12);
  AxisVector p{};
  seg->point_at(seg->length() / 2.0, p);
  EXPECT_NEAR(p[X], 10.0 + 10.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(p[Y], 10.0 - 10.0 / std::sqrt(2.0), 1e-12);
}

TEST(SegmentArc, FullCircleWithCentre) {
  // G02 I10 from (0,0): centre (10,0), a full clockwise turn.
  auto seg = make_arc_center(pt(0, 0), pt(0, 0), 2, X, Y, 10, 0, false);
  ASSERT_TRUE(seg);
  EXPECT_NEAR(seg->length(), 20.0 * kPi, 1e-12);
  AxisVector p{};
  seg->point_at(seg->length() / 4.0, p);  // cw from the left side of the circle: up
  EXPECT_NEAR(p[X], 10.0, 1e-12);
  EXPECT_NEAR(p[Y], 10.0, 1e-12);
  seg->point_at(seg->length() / 2.0, p);
  EXPECT_NEAR(p[X], 20.0, 1e-12);
  EXPECT_NEAR(p[Y], 0.0, 1e-12);
  seg->point_at(seg->length(), p);
  EXPECT_EQ(p[X], 0.0);
  EXPECT_EQ(p[Y], 0.0);
}

TEST(SegmentArc, ExtraTurns) {
  auto seg = make_arc_center(pt(10, 0), pt(0, 10), 2, X, Y, 0, 0, true, 2);
  ASSERT_TRUE(seg);
  EXPECT_NEAR(seg->length(), 10.0 * (0.5 * kPi + 4.0 * kPi), 1e-9);
}

TEST(SegmentArc, HelixLength) {
  // Full circle r=5 in XY with Z lead 3 and A turning: length sqrt(arc^2 + dz^2 + da^2).
  auto seg = make_arc_center(pt(5, 0, 0, 0), pt(5, 0, 3, 0), 3, X, Y, 0, 0, true);
  ASSERT_TRUE(seg);
  const double arc = 10.0 * kPi;
  EXPECT_NEAR(seg->length(), std::sqrt(arc * arc + 9.0), 1e-12);
  EXPECT_NEAR(seg->plane_arc_length(), arc, 1e-12);
  AxisVector p{};
  seg->point_at(seg->length() / 2.0, p);  // half way: opposite side, half the lead
  EXPECT_NEAR(p[X], -5.0, 1e-12);
  EXPECT_NEAR(p[Y], 0.0, 1e-12);
  EXPECT_NEAR(p[Z], 1.5, 1e-12);
  AxisVector t{};
  seg->tangent_at(1.0, t);
  EXPECT_NEAR(std::hypot(t[X], t[Y], t[Z]), 1.0, 1e-12);
  EXPECT_NEAR(t[Z], 3.0 / seg->length(), 1e-12);
}

TEST(SegmentArc, EndPointToleranceAndSpiral) {
  // End radius 10.005: inside 0.01 mm, accepted; the path still ends exactly there.
  auto ok = make_arc_center(pt(10, 0), pt(0, 10.005), 2, X, Y, 0, 0, true);
  ASSERT_TRUE(ok);
  AxisVector p{};
  ok->point_at(ok->length(), p);
  EXPECT_EQ(p[Y], 10.005);
  ok->point_at(ok->length() * 0.999999, p);
  EXPECT_NEAR(p[Y], 10.005, 1e-3);
  // 0.02 mm off on a 10 mm circle: rejected.
  EXPECT_EQ(make_arc_center(pt(10, 0), pt(0, 10.02), 2, X, Y, 0, 0, true).error(),
            ArcError::end_point_not_on_circle);
  // Relative tolerance on a big circle: 1e-4 * 1000 = 0.1 mm.
  EXPECT_TRUE(make_arc_center(pt(1000, 0), pt(0, 1000.05), 2, X, Y, 0, 0, true));
  EXPECT_FALSE(make_arc_center(pt(1000, 0), pt(0, 1000.2), 2, X, Y, 0, 0, true));
}

TEST(SegmentArc, CentreErrors) {
  EXPECT_EQ(make_arc_center(pt(0, 0), pt(1, 1), 2, X, Y, 0, 0, true).error(),
            ArcError::start_on_center);
  EXPECT_EQ(make_arc_center(pt(1, 0), pt(0, 1), 2, X, X, 0, 0, true).error(),
            ArcError::plane_axes_equal);
  EXPECT_EQ(make_arc_center(pt(1, 0), pt(0, 1), 2, X, Z, 0, 0, true).error(),
            ArcError::plane_axis_out_of_range);
  EXPECT_EQ(make_arc_center(pt(1, 0), pt(0, 1), 2, X, Y, NAN, 0, true).error(),
            ArcError::non_finite_input);
  EXPECT_EQ(make_arc_center(pt(1, 0), pt(0, 1), 0, X, Y, 0, 0, true).error(),
            ArcError::invalid_axis_count);
}

TEST(SegmentArc, RadiusShortAndLongArcs) {
  // (10,0) -> (0,10), |R| = 10: short arcs are quarters, long ones three quarters.
  struct Case {
    double r;
    bool ccw;
    double cx, cy, len;
  };
  const Case cases[] = {
      {10, true, 0, 0, 5 * kPi},     // G03 R10: centre at the origin, quarter
      {10, false, 10, 10, 5 * kPi},  // G02 R10: centre (10,10), quarter
      {-10, true, 10, 10, 15 * kPi},  // G03 R-10: centre (10,10), three quarters
      {-10, false, 0, 0, 15 * kPi},   // G02 R-10: origin, three quarters
  };
  for (const Case& c : cases) {
    auto seg = make_arc_radius(pt(10, 0), pt(0, 10), 2, X, Y, c.r, c.ccw);
    ASSERT_TRUE(seg) << c.r << " " << c.ccw;
    EXPECT_NEAR(seg->center_a(), c.cx, 1e-12) << c.r << " " << c.ccw;
    EXPECT_NEAR(seg->center_b(), c.cy, 1e-12) << c.r << " " << c.ccw;
    EXPECT_NEAR(seg->length(), c.len, 1e-9) << c.r << " " << c.ccw;
  }
}

TEST(SegmentArc, RadiusHalfCircleAndErrors) {
  // Chord 20, R 10: half circle; R 9.995 is short by less than 0.01: still a half circle.
  auto half = make_arc_radius(pt(-10, 0), pt(10, 0), 2, X, Y, 10, false);
  ASSERT_TRUE(half);
  EXPECT_NEAR(half->length(), 10 * kPi, 1e-9);
  AxisVector p{};
  half->point_at(half->length() / 2, p);  // cw from the left: over the top
  EXPECT_NEAR(p[Y], 10.0, 1e-9);
  auto nearly = make_arc_radius(pt(-10, 0), pt(10, 0), 2, X, Y, 9.995, false);
  ASSERT_TRUE(nearly);
  EXPECT_NEAR(nearly->length(), 10 * kPi, 1e-9);
  EXPECT_EQ(make_arc_radius(pt(-10, 0), pt(10, 0), 2, X, Y, 9.9, false).error(),
            ArcError::radius_too_small);
  EXPECT_EQ(make_arc_radius(pt(1, 1), pt(1, 1), 2, X, Y, 5, true).error(),
            ArcError::full_circle_with_radius);
  EXPECT_EQ(make_arc_radius(pt(0, 0), pt(1, 1), 2, X, Y, 0, true).error(), ArcError::zero_radius);
  EXPECT_EQ(make_arc_radius(pt(0, 0), pt(1, 1), 2, X, Y, NAN, true).error(),
            ArcError::non_finite_input);
}

TEST(SegmentArc, RadiusHelixG18) {
  // G18 G02 Z0 X20 R10 from Z20 X0 with Y 0 -> 4: quarter (short) + Y lead.
  AxisVector s{}, e{};
  s[Z] = 20;
  e[X] = 10;
  e[Z] = 10;
  e[Y] = 4;
  auto seg = make_arc_radius(s, e, 3, Z, X, 10, false);
  ASSERT_TRUE(seg);
  const double arc = 5 * kPi;
  EXPECT_NEAR(seg->length(), std::sqrt(arc * arc + 16.0), 1e-9);
  AxisVector p{};
  seg->point_at(seg->length(), p);
  EXPECT_EQ(p[Y], 4.0);
  EXPECT_EQ(p[X], 10.0);
}

TEST(SegmentArc, DescribeIsNotEmpty) {
  for (auto e : {ArcError::invalid_axis_count, ArcError::end_point_not_on_circle,
                 ArcError::full_circle_with_radius, ArcError::radius_too_small}) {
    EXPECT_FALSE(describe(e).empty());
  }
}

}  // namespace
}  // namespace nck::motion
