// #FACE / #CYL transformations: hand-computed points, round trips, the
// centre, and the C rate that limits the path speed.
#include "nck/motion/cax_transform.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace nck::motion {
namespace {

constexpr double kPi = std::numbers::pi;
// Channel of a lathe with C: X = 0, Z = 1, C = 2.
const CaxTrafo kFace{CaxTrafoKind::face, 0, 2, 0};
const CaxTrafo kCyl{CaxTrafoKind::cylinder, 0, 2, 60};

AxisVector xzc(double x, double z, double c) {
  AxisVector v{};
  v[0] = x;
  v[1] = z;
  v[2] = c;
  return v;
}

TEST(FaceTransform, HandComputedPoints) {
  // (10, 10): radius 10*sqrt(2) = 14.1421 mm at 45 deg.
  FaceMachine m = face_to_machine(10, 10, 0);
  EXPECT_NEAR(m.x_mm, 14.142135623730951, 1e-12);
  EXPECT_NEAR(m.c_deg, 45.0, 1e-12);
  // (0, 20): 20 mm at 90 deg; (-30, 0) seen from C = 170: 30 mm at 180 deg.
  m = face_to_machine(0, 20, 0);
  EXPECT_NEAR(m.x_mm, 20.0, 1e-12);
  EXPECT_NEAR(m.c_deg, 90.0, 1e-12);
  m = face_to_machine(-30, 0, 170);
  EXPECT_NEAR(m.x_mm, 30.0, 1e-12);
  EXPECT_NEAR(m.c_deg, 180.0, 1e-12);
  // (3, 4): 5 mm at atan2(4, 3) = 53.1301 deg.
  m = face_to_machine(3, 4, 0);
  EXPECT_NEAR(m.x_mm, 5.0, 1e-12);
  EXPECT_NEAR(m.c_deg, 53.13010235415598, 1e-9);
}

TEST(FaceTransform, FollowsTheNearestTurnOfC) {
  // After a full turn C is 360 + 45, not 45: it never jumps back.
  const FaceMachine m = face_to_machine(10, 10, 400);
  EXPECT_NEAR(m.c_deg, 405.0, 1e-12);
  EXPECT_NEAR(m.x_mm, 14.142135623730951, 1e-12);
  // Seen from C = 200 the point (10, 0) is reached with X = -10 at C = 180.
  const FaceMachine n = face_to_machine(10, 0, 200);
  EXPECT_NEAR(n.x_mm, -10.0, 1e-12);
  EXPECT_NEAR(n.c_deg, 180.0, 1e-12);
}

TEST(FaceTransform, CentreKeepsC) {
  const FaceMachine m = face_to_machine(0, 0, 123.0);
  EXPECT_EQ(m.x_mm, 0.0);
  EXPECT_EQ(m.c_deg, 123.0);
  const FaceMachine n = face_to_machine(1e-9, -1e-9, 7.0);  // inside kFaceCentre_mm
  EXPECT_EQ(n.c_deg, 7.0);
}

TEST(FaceTransform, RoundTrips) {
  for (double x : {-40.0, -3.5, 0.25, 12.0, 80.0})
    for (double y : {-25.0, -0.5, 0.0, 7.0, 60.0})
      for (double prev : {-720.0, -90.0, 0.0, 179.0, 1000.0}) {
        const FaceMachine m = face_to_machine(x, y, prev);
        EXPECT_LE(std::abs(m.c_deg - prev), 90.0 + 1e-9);  // the nearest of both branches
        double cx = 0, cy = 0;
        face_to_cartesian(m.x_mm, m.c_deg, cx, cy);
        EXPECT_NEAR(cx, x, 1e-9);
        EXPECT_NEAR(cy, y, 1e-9);
      }
}

TEST(FaceTransform, LeavingTheCentre) {
  // Towards +Y (90 deg) from C = 0: the lathe turns to 90 (X >= 0); the
  // mill too (90 either way: X positive preferred).
  EXPECT_NEAR(face_leave_centre_c_deg(0, 5, 0, true), 90.0, 1e-12);
  EXPECT_NEAR(face_leave_centre_c_deg(0, 5, 0, false), 90.0, 1e-12);
  // Towards -X (180 deg) from C = 10: the lathe turns to 180, the mill
  // keeps 0 and lets X go negative (turn 10 deg back).
  EXPECT_NEAR(face_leave_centre_c_deg(-1, 0, 10, true), 180.0, 1e-12);
  EXPECT_NEAR(face_leave_centre_c_deg(-1, 0, 10, false), 0.0, 1e-12);
  // From C = 700 towards 45 deg: the nearest turn 765 (lathe), 765 (mill).
  EXPECT_NEAR(face_leave_centre_c_deg(1, 1, 700, true), 765.0, 1e-12);
  EXPECT_NEAR(face_leave_centre_c_deg(1, 1, 700, false), 765.0, 1e-12);
  EXPECT_EQ(face_leave_centre_c_deg(0, 0, 33, true), 33.0);  // no direction: C stays
}

TEST(CylTransform, DevelopedLengthOnTheReferenceRadius) {
  // R = 60: 100 mm developed = 100 / 60 rad = 95.4930 deg; half the
  // circumference (60 pi mm) = 180 deg.
  EXPECT_NEAR(cyl_to_machine_c_deg(100, 60), 95.49296585513720, 1e-10);
  EXPECT_NEAR(cyl_to_machine_c_deg(60 * kPi, 60), 180.0, 1e-12);
  EXPECT_NEAR(cyl_to_developed_mm(95.49296585513720, 60), 100.0, 1e-10);
  for (double c : {-500.0, -1.0, 0.0, 33.3, 1234.5})
    EXPECT_NEAR(cyl_to_developed_mm(cyl_to_machine_c_deg(c, 60), 60), c, 1e-9);
}

TEST(CaxVector, FaceAndCylinderMapTheirAxesOnly) {
  AxisVector m = xzc(0, 0, 10);  // previous machine C = 10
  cax_to_machine(kFace, xzc(0, 50, 20), m, 3);
  EXPECT_NEAR(m[0], 20.0, 1e-12);
  EXPECT_NEAR(m[1], 50.0, 1e-12);  // Z untouched
  EXPECT_NEAR(m[2], 90.0, 1e-12);
  AxisVector back{};
  cax_to_cartesian(kFace, m, back, 3);
  EXPECT_NEAR(back[0], 0.0, 1e-12);
  EXPECT_NEAR(back[2], 20.0, 1e-12);
  AxisVector c{};
  cax_to_machine(kCyl, xzc(60, 30, 100), c, 3);
  EXPECT_NEAR(c[0], 60.0, 1e-12);
  EXPECT_NEAR(c[1], 30.0, 1e-12);
  EXPECT_NEAR(c[2], 95.49296585513720, 1e-10);
}

// A square pocket on the face, corners (+-10, +-10), followed counter-
// clockwise from (10, -10): C runs 315 -> 405 -> 495 -> 585 -> 675 in the
// machine's continuous angle when started at C = 315, X stays 14.1421 at
// the corners.
TEST(FaceTransform, SquarePocketCorners) {
  const double corners[5][2] = {{10, -10}, {10, 10}, {-10, 10}, {-10, -10}, {10, -10}};
  double c = 315.0;
  for (int i = 0; i < 4; ++i) {
    auto seg = make_line(xzc(corners[i][0], 0, corners[i][1]), xzc(corners[i + 1][0], 0, corners[i + 1][1]), 3);
    ASSERT_TRUE(seg);
    c = face_end_c_deg(kFace, *seg, c);
    EXPECT_NEAR(c, 315.0 + 90.0 * (i + 1), 1e-9);
    // Along a side the smallest radius is 10 mm, on the side's normal: the
    // C rate there is 1/10 rad/mm = 5.7296 deg/mm.
    EXPECT_NEAR(face_max_c_rate_deg_mm(kFace, *seg), 0.1 * 180 / kPi, 1e-9);
  }
}

TEST(FaceTransform, LineThroughTheCentreKeepsC) {
  auto seg = make_line(xzc(20, 0, 0), xzc(-20, 0, 0), 3);
  ASSERT_TRUE(seg);
  EXPECT_EQ(face_max_c_rate_deg_mm(kFace, *seg), 0.0);  // no division by zero
  EXPECT_NEAR(face_end_c_deg(kFace, *seg, 0.0), 0.0, 1e-12);
  // Stepping along it as the channel does: X runs 20 -> -20 through 0, C stays 0.
  AxisVector m = xzc(20, 0, 0), p{};
  for (int i = 0; i <= 400; ++i) {
    seg->point_at(seg->length() * i / 400.0, p);
    cax_to_machine(kFace, p, m, 3);
    EXPECT_NEAR(m[2], 0.0, 1e-9);
    EXPECT_NEAR(m[0], 20.0 - 40.0 * i / 400.0, 1e-9);
  }
}

TEST(FaceTransform, NearMissTurnsCHalfATurn) {
  // y = 1 passes the centre at 1 mm: C turns from ~2.86 deg to ~177.14 deg
  // with X >= 1, and the C rate peaks at 1/1 rad/mm = 57.2958 deg/mm.
  auto seg = make_line(xzc(20, 0, 1), xzc(-20, 0, 1), 3);
  ASSERT_TRUE(seg);
  const double start = std::atan2(1.0, 20.0) * 180 / kPi;
  EXPECT_NEAR(face_end_c_deg(kFace, *seg, start), 180.0 - start, 1e-9);
  EXPECT_NEAR(face_max_c_rate_deg_mm(kFace, *seg), 180 / kPi, 1e-9);
  // A line that stays away on one side: rate from its nearest end point.
  auto side = make_line(xzc(10, 0, 10), xzc(10, 0, 30), 3);
  ASSERT_TRUE(side);
  EXPECT_NEAR(face_max_c_rate_deg_mm(kFace, *side), 10.0 / 200.0 * 180 / kPi, 1e-9);
}

TEST(FaceTransform, ArcAroundTheCentreTurnsCOnce) {
  // Full circle of radius 15 about the centre: C +360, rate 1/15 rad/mm.
  auto seg = make_arc_center(xzc(15, 0, 0), xzc(15, 0, 0), 3, 0, 2, 0, 0, true);
  ASSERT_TRUE(seg);
  EXPECT_NEAR(face_end_c_deg(kFace, *seg, 0.0), 360.0, 1e-6);
  EXPECT_NEAR(face_max_c_rate_deg_mm(kFace, *seg), 180 / kPi / 15, 1e-6);
}

}  // namespace
}  // namespace nck::motion
