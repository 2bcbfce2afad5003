#include "nck/frames/rotation.hpp"

#include <cctype>
#include <cmath>
#include <numbers>

namespace nck::frames {
namespace {

constexpr std::array<std::string_view, kRotationSequenceCount> kNames = {
    "XYZ", "XYX", "XZY", "XZX", "YXZ", "YXY", "YZX", "YZY", "ZXY", "ZXZ", "ZYX", "ZYZ"};

double rad(double deg) { return deg * std::numbers::pi / 180.0; }

// cos/sin that give exact 0 and +-1 at multiples of 90 degrees, so matrices
// built from right angles compare exactly and round trips stay clean.
void cos_sin(double deg, double& c, double& s) {
  double q = deg / 90.0;
  if (std::isfinite(q) && q == std::round(q)) {
    long k = static_cast<long>(std::fmod(std::round(q), 4.0));
    if (k < 0) k += 4;
    static constexpr double kc[4] = {1, 0, -1, 0};
    static constexpr double ks[4] = {0, 1, 0, -1};
    c = kc[k];
    s = ks[k];
    return;
  }
  c = std::cos(rad(deg));
  s = std::sin(rad(deg));
}

}  // namespace

Mat3 mul(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  return r;
}

Vec3 mul(const Mat3& m, const Vec3& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
          m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

Mat3 transpose(const Mat3& m) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = m[j][i];
  return r;
}

Mat3 rot_x(double angle_deg) {
  double c, s;
  cos_sin(angle_deg, c, s);
  return {{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
}

Mat3 rot_y(double angle_deg) {
  double c, s;
  cos_sin(angle_deg, c, s);
  return {{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}};
}

Mat3 rot_z(double angle_deg) {
  double c, s;
  cos_sin(angle_deg, c, s);
  return {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
}

Mat3 rot_axis(int axis, double angle_deg) {
  if (axis == 0) return rot_x(angle_deg);
  if (axis == 1) return rot_y(angle_deg);
  return rot_z(angle_deg);
}

std::optional<RotationSequence> parse_rotation_sequence(std::string_view text) {
  if (text.size() != 3) return std::nullopt;
  char up[3];
  for (int i = 0; i < 3; ++i)
    up[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[i])));
  for (int i = 0; i < kRotationSequenceCount; ++i)
    if (std::string_view(up, 3) == kNames[i]) return static_cast<RotationSequence>(i);
  return std::nullopt;
}

std::string_view to_string(RotationSequence s) {
  auto i = static_cast<std::size_t>(s);
  return i < kNames.size() ? kNames[i] : std::string_view("ZYX");
}

int sequence_axis(RotationSequence s, int step) {
  return to_string(s)[static_cast<std::size_t>(step)] - 'X';
}

Mat3 rotation_matrix(const RotationConvention& c, const Vec3& phi_deg) {
  // Step k of the sequence turns by phi[2-k] (phi3 first, phi1 last).
  Mat3 r1 = rot_axis(sequence_axis(c.sequence, 0), phi_deg[2]);
  Mat3 r2 = rot_axis(sequence_axis(c.sequence, 1), phi_deg[1]);
  Mat3 r3 = rot_axis(sequence_axis(c.sequence, 2), phi_deg[0]);
  if (c.mode == RotationMode::extrinsic) return mul(mul(r3, r2), r1);
  return mul(mul(r1, r2), r3);
}

Mat3 plane_rotation(int first, int second, double angle_deg) {
  double c, s;
  cos_sin(angle_deg, c, s);
  Mat3 m = identity3();
  m[first][first] = c;
  m[first][second] = -s;
  m[second][first] = s;
  m[second][second] = c;
  return m;
}

}  // namespace nck::frames
