#pragma once
// Shared by the corner-blend tests (fillets and parabolas): points, blocks
// in the X/Y plane of a 3-axis machine, and a sampled distance to a segment.
#include <algorithm>
#include <cmath>

#include "nck/motion/segment.hpp"

namespace nck::motion::corner_test {

inline AxisVector p3(double x, double y, double z = 0) {
  AxisVector v{};
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

inline Segment line(AxisVector a, AxisVector b) { return *make_line(a, b, 3); }
inline Segment arc(AxisVector a, AxisVector b, double cx, double cy, bool ccw) {
  return *make_arc_center(a, b, 3, 0, 1, cx, cy, ccw);
}

// Smallest distance from q to the segment, sampled at `samples` + 1 points.
inline double distance_to(const Segment& s, const AxisVector& q, int samples) {
  double best = 1e9;
  AxisVector p{};
  for (int i = 0; i <= samples; ++i) {
    s.point_at(s.length() * i / samples, p);
    best = std::min(best, std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
  }
  return best;
}

}  // namespace nck::motion::corner_test
