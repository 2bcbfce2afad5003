#include "nck/motion/cax_transform.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace nck::motion {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

// The angle a + k * 360 nearest to `near`.
double nearest_turn(double a_deg, double near_deg) noexcept {
  return a_deg + 360.0 * std::round((near_deg - a_deg) / 360.0);
}

// Arcs (and anything not a line) are followed in this many steps.
constexpr int kArcSamples = 2048;

bool usable(const CaxTrafo& t, const Segment& seg) noexcept {
  return t.kind == CaxTrafoKind::face && t.radial >= 0 && t.c >= 0 &&
         static_cast<std::size_t>(std::max(t.radial, t.c)) < seg.axis_count();
}

}  // namespace

FaceMachine face_to_machine(double x_mm, double y_mm, double prev_c_deg) noexcept {
  const double r = std::hypot(x_mm, y_mm);
  if (!(r >= kFaceCentre_mm)) return {0.0, prev_c_deg};  // the centre (or NaN): C stays
  const double a = std::atan2(y_mm, x_mm) * kDegPerRad;
  const double c_pos = nearest_turn(a, prev_c_deg);          // X = +r
  const double c_neg = nearest_turn(a + 180.0, prev_c_deg);  // X = -r
  // Equal distance (90 deg either way) keeps X positive.
  if (std::abs(c_neg - prev_c_deg) < std::abs(c_pos - prev_c_deg)) return {-r, c_neg};
  return {r, c_pos};
}

double face_leave_centre_c_deg(double dx, double dy, double prev_c_deg, bool x_positive) noexcept {
  if (!(std::hypot(dx, dy) > 0)) return prev_c_deg;
  const double a = std::atan2(dy, dx) * kDegPerRad;
  const double own = nearest_turn(a, prev_c_deg);
  if (x_positive) return own;
  const double opposite = nearest_turn(a + 180.0, prev_c_deg);
  return std::abs(opposite - prev_c_deg) < std::abs(own - prev_c_deg) ? opposite : own;
}

void face_to_cartesian(double x_mm, double c_deg, double& cart_x_mm, double& cart_y_mm) noexcept {
  const double a = c_deg / kDegPerRad;
  cart_x_mm = x_mm * std::cos(a);
  cart_y_mm = x_mm * std::sin(a);
}

double cyl_to_machine_c_deg(double c_mm, double radius_mm) noexcept {
  return radius_mm > 0 ? c_mm / radius_mm * kDegPerRad : 0.0;
}

double cyl_to_developed_mm(double c_deg, double radius_mm) noexcept {
  return c_deg / kDegPerRad * radius_mm;
}

void cax_to_machine(const CaxTrafo& t, const AxisVector& cart, AxisVector& machine, std::size_t n) noexcept {
  const double prev_c = t.c >= 0 ? machine[static_cast<std::size_t>(t.c)] : 0.0;
  for (std::size_t j = 0; j < n && j < kMaxAxes; ++j) machine[j] = cart[j];
  if (t.c < 0 || static_cast<std::size_t>(t.c) >= n) return;
  const auto jc = static_cast<std::size_t>(t.c);
  if (t.kind == CaxTrafoKind::cylinder) {
    machine[jc] = cyl_to_machine_c_deg(cart[jc], t.radius_mm);
  } else if (t.kind == CaxTrafoKind::face && t.radial >= 0 && static_cast<std::size_t>(t.radial) < n) {
    const auto jx = static_cast<std::size_t>(t.radial);
    const FaceMachine m = face_to_machine(cart[jx], cart[jc], prev_c);
    machine[jx] = m.x_mm;
    machine[jc] = m.c_deg;
  }
}

void cax_to_cartesian(const CaxTrafo& t, const AxisVector& machine, AxisVector& cart, std::size_t n) noexcept {
  for (std::size_t j = 0; j < n && j < kMaxAxes; ++j) cart[j] = machine[j];
  if (t.c < 0 || static_cast<std::size_t>(t.c) >= n) return;
  const auto jc = static_cast<std::size_t>(t.c);
  if (t.kind == CaxTrafoKind::cylinder) {
    cart[jc] = cyl_to_developed_mm(machine[jc], t.radius_mm);
  } else if (t.kind == CaxTrafoKind::face && t.radial >= 0 && static_cast<std::size_t>(t.radial) < n) {
    const auto jx = static_cast<std::size_t>(t.radial);
    face_to_cartesian(machine[jx], machine[jc], cart[jx], cart[jc]);
  }
}

double face_max_c_rate_deg_mm(const CaxTrafo& t, const Segment& seg) noexcept {
  if (!usable(t, seg) || seg.length() <= 0) return 0.0;
  const auto jx = static_cast<std::size_t>(t.radial), jc = static_cast<std::size_t>(t.c);
  if (seg.kind() == SegmentKind::line) {
    const double x0 = seg.start_point()[jx], y0 = seg.start_point()[jc];
    const double dx = seg.end_point()[jx] - x0, dy = seg.end_point()[jc] - y0;
    const double lp = std::hypot(dx, dy);  // length in the face plane
    if (lp <= 0) return 0.0;              // the face point stands still
    const double ux = dx / lp, uy = dy / lp;
    const double d = std::abs(x0 * uy - y0 * ux);  // distance of the line from the centre
    if (d < kFaceCentre_mm) return 0.0;            // through the centre: C does not turn
    const double foot = std::clamp(-(x0 * ux + y0 * uy), 0.0, lp);
    const double r_min = std::hypot(x0 + foot * ux, y0 + foot * uy);
    return d / (r_min * r_min) * (lp / seg.length()) * kDegPerRad;
  }
  AxisVector p{};
  seg.point_at(0, p);
  double c = face_to_machine(p[jx], p[jc], 0).c_deg, rate = 0;
  const double ds = seg.length() / kArcSamples;
  for (int i = 1; i <= kArcSamples; ++i) {
    seg.point_at(ds * i, p);
    const double next = face_to_machine(p[jx], p[jc], c).c_deg;
    rate = std::max(rate, std::abs(next - c) / ds);
    c = next;
  }
  return rate;
}

double face_end_c_deg(const CaxTrafo& t, const Segment& seg, double start_c_deg) noexcept {
  if (!usable(t, seg)) return start_c_deg;
  const auto jx = static_cast<std::size_t>(t.radial), jc = static_cast<std::size_t>(t.c);
  const double x0 = seg.start_point()[jx], y0 = seg.start_point()[jc];
  const double c0 = face_to_machine(x0, y0, start_c_deg).c_deg;
  if (seg.kind() == SegmentKind::line) {
    const double x1 = seg.end_point()[jx], y1 = seg.end_point()[jc];
    const double cross = x0 * y1 - y0 * x1, dot = x0 * x1 + y0 * y1;
    const double lp = std::hypot(x1 - x0, y1 - y0);
    // Not through the centre: C turns by the angle between start and end
    // (less than half a turn); through it (or from / to it) the nearest
    // branch keeps C where it is.
    const bool via_centre = lp <= 0 || std::abs(cross) / lp < kFaceCentre_mm ||
                            std::hypot(x0, y0) < kFaceCentre_mm || std::hypot(x1, y1) < kFaceCentre_mm;
    if (via_centre) return face_to_machine(x1, y1, c0).c_deg;
    return face_to_machine(x1, y1, c0 + std::atan2(cross, dot) * kDegPerRad).c_deg;
  }
  AxisVector p{};
  double c = c0;
  const double ds = seg.length() / kArcSamples;
  for (int i = 1; i <= kArcSamples; ++i) {
    seg.point_at(ds * i, p);
    c = face_to_machine(p[jx], p[jc], c).c_deg;
  }
  return c;
}

}  // namespace nck::motion
