#pragma once
// Geometric corner blending (G61/G261 with #CONTOUR MODE [DEV PATH_DEV=..],
// docs/decisions.md, "Continuous path and corner blending"): a circular fillet
// tangent to both blocks is put in the corner, and both blocks are shortened to
// its tangent points. Lines stay lines and arcs stay arcs on their own circle,
// the fillet is an arc: the kernel executes all three exactly, by path length.
// Under STEP the corner may get a parabola instead (blend_corner_parabola,
// corner_parabola.cpp), also run by path length.
//
// The fillet radius is the largest at which (a) the corner point is no
// further than path_dev_mm from the fillet (the largest distance between
// the programmed contour and the blended one), and (b) neither block loses
// more than its allowed trim length. Setup side (preparation): pure
// functions, may be slow-ish (a bisection of ~50 steps of 2-D math).
#include <optional>

#include "nck/motion/segment.hpp"

namespace nck::motion {

// How large a blend may be.
struct BlendBounds {
  double path_dev_mm = 0;    // largest distance of the programmed corner from the blend
  double max_trim_a_mm = 0;  // path length the blend may take off the end of the block before
  double max_trim_b_mm = 0;  // and off the start of the block after
  // The share of the largest blend within those bounds to make (its radius,
  // or its parabola's leg; 0 < share <= 1): a smaller blend deviates less
  // and leaves its blocks room for their other corners.
  double size_share = 1.0;
};

struct CornerBlend {
  Segment before;         // the block before, ending at the blend's first tangent point
  Segment corner;         // the blend in the corner: a fillet (arc) or a parabola
  Segment after;          // the block after, starting at the blend's second tangent point
  double radius_mm = 0;   // of the fillet (a parabola: its leg)
  double deviation_mm = 0;  // distance of the programmed corner from the blend
  // Path length the blend removes: both trims minus the blend's length (>= 0).
  double shortfall_mm = 0;
};

// Blends the corner between a (ending at the corner) and b (starting there).
// Both must lie in one plane of two axes (a line moving only in the two
// axes, an arc without helix or extra turns, every other axis standing); the
// corner must be a real turn (not collinear, not a reversal). nullopt when
// no fillet fits: the caller keeps the sharp corner.
std::optional<CornerBlend> blend_corner(const Segment& a, const Segment& b, const BlendBounds& bounds) noexcept;

// The same corner with a parabola instead of the fillet (SegmentKind::parabola,
// STEP's blend): a quadratic Bezier with equal legs, tangent to both blocks,
// whose control point is where their tangents meet (the programmed corner
// between lines). The largest that keeps the corner within path_dev_mm of
// it and the trims within their bounds; between lines it has the closed
// form leg = 4 path_dev / |t_out - t_in|. Line-line, line-arc and arc-line
// corners only (nullopt otherwise, or when none fits); radius_mm is the leg.
std::optional<CornerBlend> blend_corner_parabola(const Segment& a, const Segment& b, const BlendBounds& bounds) noexcept;

}  // namespace nck::motion
