#pragma once
// The geometry of a motion block (no state of its own): program words
// through the offset chain to machine targets, the software limits, the
// circle in the working plane, and G74 homing of path axes.
#include <expected>

#include "nck/motion/segment.hpp"
#include "nck/prep/lookahead_window.hpp"
#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

// The offsets #SUPPRESS OFFSETS leaves out in block b.
frames::SuppressMask suppress_mask(const nc::Block& b);

// The block's axis words (radius_mm[j]: word j as a radius) taken into the
// programmed position; the machine target they lead to, inside the
// software limits.
std::expected<motion::AxisVector, Diagnostic> machine_target(const nc::Block& b, const AxisArray& radius_mm,
                                                             frames::SuppressMask mask, PlanContext& ctx);

// The channel axes of the circle's plane: those of the block's plane
// (G17/G18/G19), or the transformation's (#FACE / #CYL) when it fixes them.
struct ArcPlane {
  int first = -1, second = -1;  // channel axis indices, -1 when missing
  bool trafo = false;           // the transformation's plane: centre words I and J
};
ArcPlane arc_plane(const nc::Block& b, const PlanContext& ctx);

// A circle in plane p, from start to target (program coordinates of the
// block's map); origin: where G161 centres are measured from.
std::expected<motion::Segment, Diagnostic> arc_segment(const nc::Block& b, const ArcPlane& p,
                                                       const motion::AxisVector& start,
                                                       const motion::AxisVector& target,
                                                       const motion::AxisVector& origin, std::size_t n_axes);

// G74 X<order> Y<order>..: the axes with the same order number move
// together at rapid to their home position, group after group; the block's
// other functions (in `first`) go with the first group. Homing clears
// #PSET of the homed axes.
std::expected<PlannedBlock, Diagnostic> plan_homing(const nc::Block& b, const PlannedCommand& first, PlanContext& ctx);

}  // namespace nck::prep
