// Smoothing fine chords into cubic spans (motion/chord_smoothing.hpp,
// segment_cubic.cpp): the spans meet tangent and curvature-continuous,
// stay within the tolerance of their chords, and run by arc length.
#include "nck/motion/chord_smoothing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "nck/motion/limits.hpp"

namespace nck::motion {
namespace {

AxisVector at(double x, double y, double z = 0) {
  AxisVector v{};
  v[0] = x, v[1] = y, v[2] = z;
  return v;
}

Segment line(const AxisVector& a, const AxisVector& b) { return *make_line(a, b, 3); }

double dist(const AxisVector& a, const AxisVector& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// Distance of p from the segment a-b.
double to_chord(const AxisVector& p, const AxisVector& a, const AxisVector& b) {
  double ab2 = 0, t = 0;
  for (int i = 0; i < 3; ++i) ab2 += (b[i] - a[i]) * (b[i] - a[i]), t += (p[i] - a[i]) * (b[i] - a[i]);
  t = std::clamp(t / ab2, 0.0, 1.0);
  return dist(p, at(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])));
}

// The unit tangent's change per mm at s (numerically).
double curvature(const Segment& s, double at_mm) {
  const double h = 1e-4;
  AxisVector t0{}, t1{};
  s.tangent_at(std::max(at_mm - h, 0.0), t0);
  s.tangent_at(std::min(at_mm + h, s.length()), t1);
  const double n0 = std::hypot(t0[0], t0[1], t0[2]), n1 = std::hypot(t1[0], t1[1], t1[2]);
  return std::hypot(t1[0] / n1 - t0[0] / n0, t1[1] / n1 - t0[1] / n0, t1[2] / n1 - t0[2] / n0) /
         (std::min(at_mm + h, s.length()) - std::max(at_mm - h, 0.0));
}

TEST(ChordSmoothing, TheVertexMovesBySixthOfItsSecondDifference) {
  // Chords of 0.25 mm turning by 1 degree: the vertex moves by
  // |V0 - 2 V1 + V2| / 6 = 0.25 * 2 sin(0.5 deg) / 6 = 0.727 um.
  const double th = std::numbers::pi / 180;
  const AxisVector v0 = at(0, 0), v1 = at(0.25, 0), v2 = at(0.25 + 0.25 * std::cos(th), 0.25 * std::sin(th));
  const auto sv = smooth_vertex(line(v0, v1), line(v1, v2), 0.01);
  ASSERT_TRUE(sv);
  EXPECT_NEAR(sv->deviation_mm, 0.25 * 2 * std::sin(th / 2) / 6, 1e-12);
  EXPECT_EQ(sv->before.kind(), SegmentKind::cubic);
  EXPECT_EQ(sv->after.kind(), SegmentKind::cubic);
  // Both spans meet at S(V), start and end where the chords do elsewhere.
  EXPECT_EQ(sv->before.start_point()[0], 0.0);
  EXPECT_NEAR(dist(sv->before.end_point(), sv->after.start_point()), 0.0, 1e-15);
  EXPECT_EQ(sv->after.end_point()[0], v2[0]);
  // Tangent continuous at the vertex; zero curvature at the sharp ends
  // (the clamped spline), the same curvature on both sides of S(V).
  AxisVector ta{}, tb{};
  sv->before.tangent_at(sv->before.length(), ta);
  sv->after.tangent_at(0, tb);
  EXPECT_NEAR(dist(ta, tb), 0.0, 1e-9);
  const double k_in = curvature(sv->before, sv->before.length()), k_out = curvature(sv->after, 0);
  EXPECT_NEAR(k_in, k_out, 0.02 * k_in);
  EXPECT_NEAR(curvature(sv->before, 0), 0.0, 0.05 * k_in);
  // The spline's curvature at a knot: |V0 - 2 V1 + V2| / L^2 (|B'| = L).
  EXPECT_NEAR(k_in, 2 * std::sin(th / 2) / 0.25, 0.03 * k_in);
}

TEST(ChordSmoothing, SpansRunByArcLengthAndStayNearTheirChords) {
  const AxisVector v0 = at(0, 0, 0), v1 = at(0.3, 0.02, -0.01), v2 = at(0.55, 0.05, -0.03);
  const auto sv = smooth_vertex(line(v0, v1), line(v1, v2), 0.01);
  ASSERT_TRUE(sv);
  for (const Segment* s : {&sv->before, &sv->after}) {
    AxisVector p{}, q{}, t{};
    const AxisVector &a = s == &sv->before ? v0 : v1, &b = s == &sv->before ? v1 : v2;
    for (int k = 0; k <= 100; ++k) {
      const double mm = s->length() * k / 100.0;
      s->point_at(mm, p);
      EXPECT_LE(to_chord(p, a, b), sv->deviation_mm + 1e-12);
      s->tangent_at(mm, t);
      EXPECT_NEAR(std::hypot(t[0], t[1], t[2]), 1.0, 0.02);  // the speed law within 2 %
      if (k > 0) {  // path length per step: the arc length within 2 %
        s->point_at(s->length() * (k - 1) / 100.0, q);
        EXPECT_NEAR(dist(p, q), s->length() / 100.0, 0.02 * s->length() / 100.0);
      }
    }
    s->point_at(s->length(), p);
    EXPECT_EQ(dist(p, s->end_point()), 0.0);  // the end exactly
  }
}

TEST(ChordSmoothing, AVertexBeyondTheToleranceStaysSharp) {
  // 0.25 mm chords turning by 10 degrees move their vertex by
  // 0.25 * 2 sin(5 deg) / 6 = 7.26 um.
  const double th = 10 * std::numbers::pi / 180;
  const Segment a = line(at(0, 0), at(0.25, 0)), b = line(at(0.25, 0), at(0.25 + 0.25 * std::cos(th), 0.25 * std::sin(th)));
  EXPECT_FALSE(smooth_vertex(a, b, 0.0072));
  EXPECT_TRUE(smooth_vertex(a, b, 0.0073));
  // A right angle would be within 0.06 mm, but its spans' speed law strays.
  const Segment c = line(at(0.25, 0), at(0.25, 0.25));
  EXPECT_FALSE(smooth_vertex(a, c, 0.06));
  // Chords of very different lengths: the uniform spline's speed law strays.
  EXPECT_FALSE(smooth_vertex(line(at(0, 0), at(0.1, 0)), line(at(0.1, 0), at(5, 0.01)), 0.01));
}

TEST(ChordSmoothing, ASpanAfterASpanKeepsItsChord) {
  // Three chords: smoothing the second vertex keeps the first span's
  // smoothed start and its thirds, and moves only its end.
  const AxisVector v0 = at(0, 0), v1 = at(0.25, 0), v2 = at(0.5, 0.004), v3 = at(0.75, 0.012);
  const auto first = smooth_vertex(line(v0, v1), line(v1, v2), 0.01);
  ASSERT_TRUE(first);
  const auto second = smooth_vertex(first->after, line(v2, v3), 0.01);
  ASSERT_TRUE(second);
  EXPECT_EQ(second->before.start_point(), first->after.start_point());
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(second->before.cubic_p1(k), first->after.cubic_p1(k), 1e-15);
    EXPECT_NEAR(second->before.cubic_p2(k), first->after.cubic_p2(k), 1e-15);
  }
  // S(V2) = V2 + (V1 - 2 V2 + V3) / 6.
  EXPECT_NEAR(second->before.end_point()[1], 0.004 + (0 - 0.008 + 0.012) / 6, 1e-15);
}

TEST(ChordSmoothing, ARemainderFollowsTheSameCurve) {
  const auto sv = smooth_vertex(line(at(0, 0), at(0.25, 0)), line(at(0.25, 0), at(0.5, 0.01)), 0.01);
  ASSERT_TRUE(sv);
  const Segment r = sv->after.remainder(0.4 * sv->after.length());
  AxisVector p{}, q{};
  EXPECT_NEAR(r.length(), 0.6 * sv->after.length(), 0.02 * sv->after.length());
  for (int k = 0; k <= 10; ++k) {
    r.point_at(r.length() * k / 10.0, p);
    // On the original curve: its nearest sampled point is within a hair.
    double best = 1;
    for (int n = 0; n <= 2000; ++n) {
      sv->after.point_at(sv->after.length() * n / 2000.0, q);
      best = std::min(best, dist(p, q));
    }
    EXPECT_LT(best, 1e-4);
  }
}

TEST(ChordSmoothing, CurvatureLimitsTheSpeedAsARadiusWould) {
  // A span whose curvature peaks near 1/r: path_limits gives about the
  // speed an arc of radius r gets (v^2 / r within a / sqrt 2).
  const double th = 10 * std::numbers::pi / 180;
  const AxisVector v0 = at(0, 0), v1 = at(1, 0), v2 = at(1 + std::cos(th), std::sin(th));
  const auto sv = smooth_vertex(line(v0, v1), line(v1, v2), 0.1);
  ASSERT_TRUE(sv);
  std::array<AxisDynamics, 3> axes{};
  for (auto& a : axes) a = AxisDynamics{500, 2500, 2500};
  const PathLimits l = path_limits(sv->before, axes, SlopeProfile::step);
  const double kappa = curvature(sv->before, sv->before.length());
  EXPECT_NEAR(l.v_max_mm_s, std::sqrt(2500 / std::numbers::sqrt2 / kappa), 0.05 * l.v_max_mm_s);
  // Jerk-limited: the turning acceleration's change holds it lower.
  for (auto& a : axes) a.tr = RampTimes{0.05, 0.05, 0.05, 0.05};
  EXPECT_LT(path_limits(sv->before, axes, SlopeProfile::trapez).v_max_mm_s, l.v_max_mm_s);
}

}  // namespace
}  // namespace nck::motion
