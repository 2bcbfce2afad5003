#pragma once
// Smoothing fine chords (docs/decisions.md, "Smoothing fine chords"): under
// a jerk-limited slope a programmed polyline whose vertices may move by the
// tolerance becomes the uniform cubic B-spline with the programmed vertices
// as its control points, clamped where a vertex stays sharp. Each chord
// becomes one span (SegmentKind::cubic) of its own block: its inner Bezier
// control points are the chord's thirds, its ends the smoothed vertices
// S(V) = V + (V_before - 2 V + V_after) / 6. Where two spans meet the path
// is curvature-continuous, so a jerk-limited slope passes at the speed the
// curvature allows instead of the speed a kink allows. Each span lies in
// the hull of its chord and its moved ends: within |S(V) - V| of the chord.
// Setup side (preparation).
#include <optional>

#include "nck/motion/segment.hpp"

namespace nck::motion {

struct SmoothedVertex {
  Segment before;           // the chord before, now ending at S(V)
  Segment after;            // the chord after, now starting at S(V)
  double deviation_mm = 0;  // |S(V) - V|
};

// Smooths the vertex V between `before` (a line, or a span whose end is
// still its programmed vertex) and `after` (a line). nullopt where the
// vertex would move more than path_dev_mm, more than three axes move, an
// axis moves that does not count for the path length, or a span's speed
// law would stray (make_cubic): the caller keeps the corner as it is.
std::optional<SmoothedVertex> smooth_vertex(const Segment& before, const Segment& after, double path_dev_mm) noexcept;

}  // namespace nck::motion
