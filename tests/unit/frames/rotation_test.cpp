// Rotation conventions (P-CHAN-00393/00394) against hand-computed matrices.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "nck/frames/rotation.hpp"

namespace nck::frames {
namespace {

void expect_mat(const Mat3& got, const Mat3& want, double tol = 1e-12) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(got[i][j], want[i][j], tol) << "element " << i << j;
}

// Literal 90-degree matrices, written out by hand (not computed by the code under test).
const Mat3 kRx90{{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}};
const Mat3 kRy90{{{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}}};
const Mat3 kRz90{{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}};

Mat3 product(const Mat3& a, const Mat3& b) {  // test-local, independent of mul()
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}

TEST(Rotation, ElementaryMatricesAt90And30Degrees) {
  expect_mat(rot_x(90), kRx90);
  expect_mat(rot_y(90), kRy90);
  expect_mat(rot_z(90), kRz90);
  const double c = 0.8660254037844387, s = 0.5;  // cos 30, sin 30
  expect_mat(rot_z(30), {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}});
  expect_mat(rot_y(30), {{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}});
  expect_mat(rot_x(-30), {{{1, 0, 0}, {0, c, s}, {0, -s, c}}});
}

TEST(Rotation, DefaultZyxIntrinsicIsRzRyRx) {
  RotationConvention def;  // P-CHAN-00394 ZYX, P-CHAN-00393 intrinsic
  // phi3 = 90 about Z, then phi2 = 90 about Y': Rz(90)*Ry(90) by hand.
  expect_mat(rotation_matrix(def, {0, 90, 90}), {{{0, -1, 0}, {0, 0, 1}, {-1, 0, 0}}});
  // The X axis of the CS then points along -Z of the parent.
  Vec3 x = mul(rotation_matrix(def, {0, 90, 90}), Vec3{1, 0, 0});
  EXPECT_NEAR(x[2], -1.0, 1e-12);
}

TEST(Rotation, ExtrinsicReversesTheProduct) {
  RotationConvention ext{RotationSequence::zyx, RotationMode::extrinsic};
  // Ry(90)*Rz(90) by hand.
  expect_mat(rotation_matrix(ext, {0, 90, 90}), {{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}});
}

TEST(Rotation, ZyxClosedFormAt30_45_60) {
  const double x = 30 * std::numbers::pi / 180, y = 45 * std::numbers::pi / 180,
               z = 60 * std::numbers::pi / 180;
  const double cx = std::cos(x), sx = std::sin(x), cy = std::cos(y), sy = std::sin(y),
               cz = std::cos(z), sz = std::sin(z);
  Mat3 want{{{cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx},
             {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx},
             {-sy, cy * sx, cy * cx}}};
  expect_mat(rotation_matrix({}, {30, 45, 60}), want);
}

TEST(Rotation, ZyzEulerClosedForm) {
  // Proper Euler Z-Y'-Z'': alpha = phi3 first, beta = phi2, gamma = phi1.
  const double a = 20 * std::numbers::pi / 180, b = 35 * std::numbers::pi / 180,
               g = 50 * std::numbers::pi / 180;
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b),
               cg = std::cos(g), sg = std::sin(g);
  Mat3 want{{{ca * cb * cg - sa * sg, -ca * cb * sg - sa * cg, ca * sb},
             {sa * cb * cg + ca * sg, -sa * cb * sg + ca * cg, sa * sb},
             {-sb * cg, sb * sg, cb}}};
  expect_mat(rotation_matrix({RotationSequence::zyz, RotationMode::intrinsic}, {50, 35, 20}), want);
}

TEST(Rotation, AllTwelveSequencesAtRightAngles) {
  const Mat3* lit[3] = {&kRx90, &kRy90, &kRz90};
  const char* names[12] = {"XYZ", "XYX", "XZY", "XZX", "YXZ", "YXY",
                           "YZX", "YZY", "ZXY", "ZXZ", "ZYX", "ZYZ"};
  for (int i = 0; i < 12; ++i) {
    SCOPED_TRACE(names[i]);
    auto seq = parse_rotation_sequence(names[i]);
    ASSERT_TRUE(seq.has_value());
    EXPECT_EQ(static_cast<int>(*seq), i);
    EXPECT_EQ(to_string(*seq), names[i]);
    const Mat3& a = *lit[names[i][0] - 'X'];
    const Mat3& b = *lit[names[i][1] - 'X'];
    const Mat3& c = *lit[names[i][2] - 'X'];
    expect_mat(rotation_matrix({*seq, RotationMode::intrinsic}, {90, 90, 90}), product(product(a, b), c));
    expect_mat(rotation_matrix({*seq, RotationMode::extrinsic}, {90, 90, 90}), product(product(c, b), a));
    // One angle only: the step that uses it alone is the elementary turn.
    expect_mat(rotation_matrix({*seq, RotationMode::intrinsic}, {0, 0, 90}), a);
    expect_mat(rotation_matrix({*seq, RotationMode::extrinsic}, {90, 0, 0}), c);
  }
}

TEST(Rotation, ExtrinsicEqualsIntrinsicOfReversedSequence) {
  for (int i = 0; i < kRotationSequenceCount; ++i) {
    auto seq = static_cast<RotationSequence>(i);
    std::string rev(to_string(seq).rbegin(), to_string(seq).rend());
    auto rseq = parse_rotation_sequence(rev);
    ASSERT_TRUE(rseq.has_value()) << rev;
    Mat3 e = rotation_matrix({seq, RotationMode::extrinsic}, {12, -47, 133});
    Mat3 r = rotation_matrix({*rseq, RotationMode::intrinsic}, {133, -47, 12});
    expect_mat(e, r, 1e-12);
    // Orthonormal: R * R^T = I.
    expect_mat(mul(e, transpose(e)), identity3(), 1e-12);
  }
}

TEST(Rotation, ParseRejectsUnknownSequences) {
  EXPECT_FALSE(parse_rotation_sequence("XXY").has_value());
  EXPECT_FALSE(parse_rotation_sequence("ZY").has_value());
  EXPECT_FALSE(parse_rotation_sequence("").has_value());
  EXPECT_EQ(parse_rotation_sequence("zyz"), RotationSequence::zyz);
}

TEST(Rotation, PlaneRotationTurnsFirstTowardsSecondAxis) {
  Vec3 p = mul(plane_rotation(0, 1, 30), Vec3{1, 0, 0});  // G17
  EXPECT_NEAR(p[0], 0.8660254037844387, 1e-12);
  EXPECT_NEAR(p[1], 0.5, 1e-12);
  Vec3 q = mul(plane_rotation(2, 0, 90), Vec3{0, 0, 1});  // G18: Z -> X
  EXPECT_NEAR(q[0], 1.0, 1e-12);
  EXPECT_NEAR(q[2], 0.0, 1e-12);
}

}  // namespace
}  // namespace nck::frames
