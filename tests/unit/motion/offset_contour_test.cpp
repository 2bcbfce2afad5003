// Plane geometry of tool radius compensation (offset_contour.hpp), against
// points worked out by hand. Signed offset o: + left of travel (G41).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "nck/motion/offset_contour.hpp"

namespace nck::motion::trc {
namespace {

constexpr double kTol = 1e-9;

Element line(Vec2 s, Vec2 e) { return {false, false, s, e, {}}; }
Element arc(Vec2 s, Vec2 e, Vec2 c, bool ccw) { return {true, ccw, s, e, c}; }

void expect_near(Vec2 got, Vec2 want) {
  EXPECT_NEAR(got.a, want.a, kTol);
  EXPECT_NEAR(got.b, want.b, kTol);
}

TEST(OffsetContour, TangentsOfLinesAndArcs) {
  expect_near(tangent_start(line({0, 0}, {0, 40})), {0, 1});
  // counter-clockwise about the origin, starting on +a: heading +b
  expect_near(tangent_start(arc({10, 0}, {0, 10}, {0, 0}, true)), {0, 1});
  expect_near(tangent_end(arc({10, 0}, {0, 10}, {0, 0}, true)), {-1, 0});
  // clockwise from (0,32) about (8,32): heading +b
  expect_near(tangent_start(arc({0, 32}, {8, 40}, {8, 32}, false)), {0, 1});
}

TEST(OffsetContour, OffsetRadiusShrinksOnTheCentreSide) {
  // left of a ccw arc is the centre side: R - o
  EXPECT_NEAR(offset_radius(arc({3, 0}, {0, 3}, {0, 0}, true), 5), -2, kTol);
  EXPECT_NEAR(offset_radius(arc({3, 0}, {0, 3}, {0, 0}, true), -5), 8, kTol);
  EXPECT_NEAR(offset_radius(arc({0, 32}, {8, 40}, {8, 32}, false), 5), 13, kTol);
  expect_near(offset_end(arc({0, 32}, {8, 40}, {8, 32}, false), 5), {8, 45});
}

TEST(OffsetContour, OutsideCornerGetsAnArcAboutTheCorner) {
  // up the left side of a rectangle, then right along the top; tool left (outside)
  const Corner k = corner(line({0, 0}, {0, 40}), line({0, 40}, {60, 40}), 5);
  EXPECT_EQ(k.kind, CornerKind::outside);
  expect_near(k.end_a, {-5, 40});
  expect_near(k.start_b, {0, 45});
  expect_near(k.center, {0, 40});
  EXPECT_FALSE(k.arc_ccw);  // right turn: clockwise round the corner
  // the same corner with the tool right (G42) is an inside corner at (5, 35)
  const Corner in = corner(line({0, 0}, {0, 40}), line({0, 40}, {60, 40}), -5);
  EXPECT_EQ(in.kind, CornerKind::inside);
  expect_near(in.end_a, {5, 35});
  expect_near(in.start_b, {5, 35});
}

TEST(OffsetContour, InsideCornerOfAPocketIsTheIntersection) {
  const Corner k = corner(line({30, 0}, {60, 0}), line({60, 0}, {60, 40}), 5);
  EXPECT_EQ(k.kind, CornerKind::inside);
  expect_near(k.end_a, {55, 5});
  // 45 degree corner: the intersection lies r / tan(22.5 deg) back along the first line
  const Corner d = corner(line({0, 0}, {10, 0}), line({10, 0}, {20, 10}), 1);
  EXPECT_EQ(d.kind, CornerKind::inside);
  expect_near(d.end_a, {10 - std::tan(std::numbers::pi / 8), 1});
}

TEST(OffsetContour, LineIntoArcInsideCorner) {
  // +a line, then ccw about (20, 0) heading -b: a right turn; tool right (o = -5)
  // is inside. Offset line b = -5, offset circle radius 15: a = 20 - sqrt(200).
  const Corner k = corner(line({0, 0}, {10, 0}), arc({10, 0}, {30, 0}, {20, 0}, true), -5);
  EXPECT_EQ(k.kind, CornerKind::inside);
  expect_near(k.end_a, {20 - std::sqrt(200.0), -5});
}

TEST(OffsetContour, TangentTransitionNeedsNothing) {
  // line up into a clockwise arc that continues upwards
  const Corner k = corner(line({0, 0}, {0, 32}), arc({0, 32}, {8, 40}, {8, 32}, false), 5);
  EXPECT_EQ(k.kind, CornerKind::smooth);
  expect_near(k.end_a, {-5, 32});
  expect_near(k.start_b, {-5, 32});
}

TEST(OffsetContour, ReversalIsAnOutsideHalfTurn) {
  const Corner k = corner(line({0, 0}, {10, 0}), line({10, 0}, {0, 0}), 2);
  EXPECT_EQ(k.kind, CornerKind::outside);
  expect_near(k.end_a, {10, 2});
  expect_near(k.start_b, {10, -2});
}

TEST(OffsetContour, SweepAndDirection) {
  EXPECT_NEAR(sweep_rad({0, 0}, {10, 0}, {0, 10}, true), std::numbers::pi / 2, kTol);
  EXPECT_NEAR(sweep_rad({0, 0}, {10, 0}, {0, 10}, false), 1.5 * std::numbers::pi, kTol);
  EXPECT_NEAR(sweep_rad({0, 0}, {10, 0}, {10, 0}, true), 2 * std::numbers::pi, kTol);
  // slot bottom 6 mm wide, tool radius 5: the inside corners cross over
  const Element bottom = line({20, -10}, {26, -10});
  EXPECT_FALSE(keeps_direction(bottom, {25, -5}, {21, -5}));
  EXPECT_TRUE(keeps_direction(bottom, {21, -5}, {25, -5}));
  // an arc shortened past its end runs backwards
  const Element a = arc({10, 0}, {0, 10}, {0, 0}, true);
  const double deg = std::numbers::pi / 180;
  EXPECT_TRUE(keeps_direction(a, {5 * std::cos(10 * deg), 5 * std::sin(10 * deg)},
                              {5 * std::cos(80 * deg), 5 * std::sin(80 * deg)}));
  EXPECT_FALSE(keeps_direction(a, {5 * std::cos(80 * deg), 5 * std::sin(80 * deg)},
                               {5 * std::cos(10 * deg), 5 * std::sin(10 * deg)}));
}


TEST(OffsetContour, PiecesCross) {
  // Two lines crossing at X23 Y-5 inside both.
  EXPECT_TRUE(pieces_cross(line({25, 0}, {21, -10}), line({21, 0}, {25, -10})));
  // ... but not where the crossing lies beyond one of them.
  EXPECT_FALSE(pieces_cross(line({25, 0}, {24, -2.5}), line({21, 0}, {25, -10})));
  // Touching at a shared end (a closed contour) and parallel lines: no crossing.
  EXPECT_FALSE(pieces_cross(line({0, 0}, {10, 0}), line({10, 0}, {10, 10})));
  EXPECT_FALSE(pieces_cross(line({0, 0}, {10, 0}), line({0, 1}, {10, 1})));
  EXPECT_FALSE(pieces_cross(line({0, 0}, {10, 0}), line({5, 0}, {15, 0})));
  // A line through a quarter arc R5 about the origin (X0..5, Y0..5): it
  // meets the circle at X3 Y4 (on the arc) and X3 Y-4 (not on it).
  const Element q = arc({5, 0}, {0, 5}, {0, 0}, true);
  EXPECT_TRUE(pieces_cross(q, line({3, -6}, {3, 6})));
  EXPECT_FALSE(pieces_cross(q, line({3, -6}, {3, 0})));
  // The same line against the arc run the other way round (the other
  // three quarters, clockwise from X5 Y0 to X0 Y5): it meets X3 Y-4.
  EXPECT_TRUE(pieces_cross(arc({5, 0}, {0, 5}, {0, 0}, false), line({3, -6}, {3, 0})));
  // Tangent touch (a slot exactly as wide as the tool): no crossing.
  const double m = 5 / std::sqrt(2.0);  // the arc's middle, tangent direction (-1, 1)
  EXPECT_FALSE(pieces_cross(q, line({m + 1, m - 1}, {m - 1, m + 1})));
  EXPECT_TRUE(pieces_cross(q, line({m + 1, m - 1.1}, {m - 1, m + 0.9})));
  // Two arcs R5 about X20 Y0 and X26 Y0 meet at X23 Y4 and X23 Y-4.
  EXPECT_TRUE(pieces_cross(arc({20, 5}, {25, 0}, {20, 0}, false), arc({21, 0}, {26, 5}, {26, 0}, false)));
  // The second arc run the long way (clockwise from X26 Y5 to X21 Y0, by
  // X31 Y0 and X26 Y-5): it passes X23 Y-4 only, which the first does not reach.
  EXPECT_FALSE(pieces_cross(arc({20, 5}, {25, 0}, {20, 0}, false), arc({26, 5}, {21, 0}, {26, 0}, false)));
}

TEST(OffsetContour, LinearCornerOfG25) {
  // Turn of 90 deg: tangents +X from X0 Y5 and -Y into X5 Y0 meet at X5 Y5.
  LinearCorner lc = linear_corner({0, 5}, {1, 0}, {5, 0}, {0, -1}, 5);
  ASSERT_EQ(lc.n, 1);
  expect_near(lc.p[0], {5, 5});
  // Turn of 45 deg: +X from X0 Y5 and (1, -1)/sqrt 2 into the offset start
  // X5/sqrt2 Y5/sqrt2 of a corner at the origin: they meet on Y5 at X5 tan 22.5.
  const double h = 5 / std::sqrt(2.0);
  lc = linear_corner({0, 5}, {1, 0}, {h, h}, {1 / std::sqrt(2.0), -1 / std::sqrt(2.0)}, 5);
  ASSERT_EQ(lc.n, 1);
  expect_near(lc.p[0], {5 * std::tan(std::numbers::pi / 8), 5});
  // Reversal (180 deg): +X ending at X10 Y5, -X starting at X10 Y-5: both
  // extended by 5 to X15, joined by a line.
  lc = linear_corner({10, 5}, {1, 0}, {10, -5}, {-1, 0}, 5);
  ASSERT_EQ(lc.n, 2);
  expect_near(lc.p[0], {15, 5});
  expect_near(lc.p[1], {15, -5});
}

}  // namespace
}  // namespace nck::motion::trc
