#pragma once
// The path limits of what corner blending puts into a chain (docs/decisions.md,
// "Continuous path and corner blending"): a fillet, and the arcs it joins
// (STEP). Every plane axis must stay within its a_max (P-AXIS-00008, the hard
// cap of every acceleration) in every cycle, so the vector sum of the
// along-path and the across-path (centripetal) acceleration is held within the
// smaller a_max of the two plane axes; the along-path part stays within the
// feed accelerations, as on a line. Setup side (preparation).
#include <span>

#include "nck/motion/limits.hpp"
#include "nck/motion/segment.hpp"

namespace nck::prep {

struct BlendDynamics {
  std::span<const motion::AxisDynamics> feed;  // G1/G2/G3 dynamics per axis (weighted)
  std::span<const double> a_max_mm_s2;          // hard cap per axis (weighted)
};

// A fillet is meant to be run through at one speed: speeding up or braking
// on it gets at least 25 % of the plane axes' feed acceleration, and as
// much more (up to the feed acceleration) as its turn at feed_mm_s leaves
// of a_max; the turn gets the rest (v <= sqrt(a_n r), never below the feed
// where the 25 % let it pass at the feed). The path brakes across a chain
// of fillets with their gentlest deceleration.
motion::PathLimits fillet_limits(const motion::Segment& fillet, const BlendDynamics& d, double feed_mm_s);

// An arc next to a fillet: at its top speed l.v_max_mm_s (which no
// override exceeds) its centripetal acceleration a_n = v^2/r leaves
// sqrt(a_max^2 - a_n^2) for speeding up and braking (the feed accelerations
// at most) instead of the even a/sqrt 2 split path_limits gives every arc.
// Only raises l, and only for a plain arc in the plane under STEP: its
// a_acc when the fillet lies before it (`out_of_fillet`), its a_dec when it
// lies after it. An arc's braking into an exact stop keeps the planner's
// a_dec, from which the planner took the first step of the block after the
// stop (CornerUnit::start_acceleration).
void widen_arc_limits(const motion::Segment& arc, const BlendDynamics& d, bool out_of_fillet, motion::PathLimits& l);

// The first step of the block after a fillet when the path passes in from
// it (STEP): the cycle that crosses the fillet's end keeps its speed, so
// the step after it turns by at most half the fillet's centripetal
// acceleration (what the crossing chord still lay on the fillet) plus what
// the next block itself turns at one step faster; speeding up or braking
// gets what that leaves of a_max, less what the crossing chord's lean and
// shortening add along the path (next's own limits apply as well). The
// same bound holds the step into a fillet (`next` then the block before).
double pass_acceleration(const motion::Segment& fillet, const motion::PathLimits& fillet_l,
                         const motion::Segment& next, const motion::PathLimits& next_l, const BlendDynamics& d,
                         double cycle_s);

// A parabola (STEP's corner blend, SegmentKind::parabola) is run at one
// speed too: at path speed v each plane axis accelerates constantly by
// v^2 times its share of the curve's second derivative; v is the largest
// at which that plus 5 % of the feed acceleration (along the path, a
// feedhold on it) stays within each axis's own a_max.
motion::PathLimits parabola_limits(const motion::Segment& parabola, const BlendDynamics& d);

// pass_acceleration for a parabola, per axis: half its constant
// acceleration plus the other block's turn (signed, the vector sum per
// axis), the rest of each axis's a_max for speeding up or braking along the
// other block's tangent at the joint. other_after: `other` follows the
// parabola (else it is the block before).
double parabola_pass_acceleration(const motion::Segment& parabola, const motion::PathLimits& parabola_l,
                                  const motion::Segment& other, const motion::PathLimits& other_l, bool other_after,
                                  const BlendDynamics& d, double cycle_s);

}  // namespace nck::prep
