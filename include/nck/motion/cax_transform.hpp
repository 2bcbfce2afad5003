#pragma once
// Kinematic transformations of C-axis machining (#FACE, #CYL): the program
// describes the contour in Cartesian coordinates, the machine moves a radial
// axis (X) and the spindle as rotary axis C. Pure functions, noexcept and
// allocation-free: the planner uses them at setup time, the channel every
// cycle (docs/decisions.md, "C axis").
//
// Face (#FACE [X, C]): the programmed point (x, y) on the face, y written
// under the C name in mm, is the machine point at radius X and angle C:
//   x = X cos C,  y = X sin C   (C in degrees, counter-clockwise positive).
// Lateral surface (#CYL [Z, C, X<R>]): the programmed C is the developed
// length in mm on the reference radius R: C_deg = C_mm * 180 / (pi R).
#include <cstddef>
#include <cstdint>

#include "nck/motion/axis_vector.hpp"
#include "nck/motion/segment.hpp"

namespace nck::motion {

enum class CaxTrafoKind : std::uint8_t { none, face, cylinder };

struct CaxTrafo {
  CaxTrafoKind kind = CaxTrafoKind::none;
  std::int8_t radial = -1;  // channel index of the radial axis (face: X); -1 none
  std::int8_t c = -1;       // channel index of the C axis
  double radius_mm = 0;     // #CYL reference radius
};

// Below this radius (mm) the face point is the centre: C keeps its angle.
inline constexpr double kFaceCentre_mm = 1e-6;

struct FaceMachine {
  double x_mm = 0;   // radial axis, may be negative (see face_to_machine)
  double c_deg = 0;  // not wrapped: continuous with the previous set point
};

// The machine (X, C) of the face point (x, y). Of the two solutions (r, a)
// and (-r, a + 180 deg), and of all their turns, the one whose C is nearest
// prev_c_deg: C never jumps, and a contour through the centre passes it with
// X changing sign instead of C turning half a turn at once. At the centre
// C keeps prev_c_deg. rt
FaceMachine face_to_machine(double x_mm, double y_mm, double prev_c_deg) noexcept;
// The face point of machine (X, C). rt
void face_to_cartesian(double x_mm, double c_deg, double& cart_x_mm, double& cart_y_mm) noexcept;

// #CYL: developed length (mm) on radius r <-> C angle (deg). rt
double cyl_to_machine_c_deg(double c_mm, double radius_mm) noexcept;
double cyl_to_developed_mm(double c_deg, double radius_mm) noexcept;

// Face: the C from which a line leaving the centre in direction (dx, dy)
// starts. x_positive (lathe, cax_face_id 1): the direction's own angle, the
// turn nearest prev_c_deg, so X stays >= 0; otherwise the direction or its
// opposite, whichever is nearer (a turn of at most 90 deg). rt
double face_leave_centre_c_deg(double dx, double dy, double prev_c_deg, bool x_positive) noexcept;

// The whole set point: `cart` (program side, Cartesian) to `machine`, whose
// C holds the previous machine C on entry (the face branch follows it).
// Axes other than the transformed ones are copied. rt
void cax_to_machine(const CaxTrafo& t, const AxisVector& cart, AxisVector& machine, std::size_t n) noexcept;
// And back (for positions reported in program coordinates). rt
void cax_to_cartesian(const CaxTrafo& t, const AxisVector& machine, AxisVector& cart, std::size_t n) noexcept;

// Face: the largest |dC/ds| (deg per mm of Cartesian path) along the
// segment: d / r_min^2 for a line (d its distance from the centre, r_min the
// smallest radius on it; 0 through the centre), sampled for an arc. setup
double face_max_c_rate_deg_mm(const CaxTrafo& t, const Segment& seg) noexcept;
// Face: the machine C at the segment's end when the segment is followed
// from start_c_deg in small steps (as the channel does). setup
double face_end_c_deg(const CaxTrafo& t, const Segment& seg, double start_c_deg) noexcept;

}  // namespace nck::motion
