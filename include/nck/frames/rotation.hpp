#pragma once
// Rotation conventions for coordinate systems (#CS/#ACS) and the plane
// rotation (#ROTATION). Plain 3x3 arrays, row-major; matrices act on column
// vectors: v_parent = R * v_child.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace nck::frames {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<std::array<double, 3>, 3>;

constexpr Mat3 identity3() { return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}; }

Mat3 mul(const Mat3& a, const Mat3& b);
Vec3 mul(const Mat3& m, const Vec3& v);
Mat3 transpose(const Mat3& m);  // = inverse for a rotation

// Elementary rotations about the fixed axis 0=X, 1=Y, 2=Z (mathematically
// positive, right-handed).
Mat3 rot_x(double angle_deg);
Mat3 rot_y(double angle_deg);
Mat3 rot_z(double angle_deg);
Mat3 rot_axis(int axis, double angle_deg);

// P-CHAN-00394: the 12 sequences, letters = order in which the rotations
// are carried out. Enumerators in the parameter's documented order.
enum class RotationSequence : std::uint8_t {
  xyz, xyx, xzy, xzx, yxz, yxy, yzx, yzy, zxy, zxz, zyx, zyz
};
inline constexpr int kRotationSequenceCount = 12;

// P-CHAN-00393: 0 intrinsic (about the rotated axes), 1 extrinsic (fixed).
enum class RotationMode : std::uint8_t { intrinsic, extrinsic };

struct RotationConvention {
  RotationSequence sequence = RotationSequence::zyx;  // P-CHAN-00394 default
  RotationMode mode = RotationMode::intrinsic;        // P-CHAN-00393 default
};

// "ZYX" (any case) -> zyx; nullopt for anything else.
std::optional<RotationSequence> parse_rotation_sequence(std::string_view text);
std::string_view to_string(RotationSequence s);  // "ZYX"
// Axis index (0..2) of step 0..2 of a sequence.
int sequence_axis(RotationSequence s, int step);

// Rotation matrix of a CS with angles phi1..phi3 (the 4th..6th value of
// #CS [v1,v2,v3,phi1,phi2,phi3]).
// Angle assignment: step 1 of the sequence uses phi3, step 2 phi2, step 3
// phi1. For the default ZYX this is the documented "phi3 about Z, then phi2
// about Y', then phi1 about X''", and the same rule serves all 12 sequences.
// Intrinsic: R = R_s1(phi3) * R_s2(phi2) * R_s3(phi1) (each turn about the
// already turned axes). Extrinsic: the same turns about the fixed axes, so
// the product is reversed: R = R_s3(phi1) * R_s2(phi2) * R_s1(phi3).
Mat3 rotation_matrix(const RotationConvention& c, const Vec3& phi_deg);

// Rotation by angle_deg in a plane given by two axis indices (positive from
// `first` towards `second`), as a 3x3 matrix on the main axes.
Mat3 plane_rotation(int first, int second, double angle_deg);

}  // namespace nck::frames
