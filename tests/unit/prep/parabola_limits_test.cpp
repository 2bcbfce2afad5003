// The limits of a parabolic corner blend (issue 30): the mill's plane axes
// (a_max 3000, feed accelerations 2500 mm/s^2, vb 500 mm/s). At a right
// angle between lines with legs L the axis along the first leg brakes to 0
// and the other speeds up from 0 within the parabola: each by v^2 / (2 L)
// at path speed v, held with 5 % of the feed acceleration (along the path)
// within 99 % of a_max: v = sqrt(2 L (0.99 a_max - 0.05 a)).
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "nck/motion/corner_blend.hpp"
#include "nck/prep/blend_limits.hpp"

namespace nck::prep {
namespace {

motion::AxisVector p3(double x, double y) {
  motion::AxisVector v{};
  v[0] = x;
  v[1] = y;
  return v;
}

struct Mill {
  std::array<motion::AxisDynamics, 3> feed{};
  std::array<double, 3> a_max{3000, 3000, 2500};
  Mill() {
    for (auto& f : feed) f = {500, 2500, 2500, {}, 0};
  }
  BlendDynamics dyn() const { return {feed, a_max}; }
};

motion::CornerBlend corner(double x0, double y0, double x1, double y1, double x2, double y2, double dev) {
  const motion::Segment a = *motion::make_line(p3(x0, y0), p3(x1, y1), 3);
  const motion::Segment b = *motion::make_line(p3(x1, y1), p3(x2, y2), 3);
  return *motion::blend_corner_parabola(a, b, {dev, 0.45 * a.length(), 0.45 * b.length()});
}

TEST(ParabolaLimits, RightAngleAlongTheAxesEntersAtTheClosedForm) {
  const Mill m;
  const motion::CornerBlend cb = corner(0, 0, 5, 0, 5, 5, 0.01);
  const double leg = 0.04 / std::sqrt(2.0);
  const motion::PathLimits l = parabola_limits(cb.corner, m.dyn());
  EXPECT_NEAR(l.v_max_mm_s, std::sqrt(2 * leg * (0.99 * 3000 - 0.05 * 2500)), 1e-9);
  EXPECT_NEAR(l.v_max_mm_s, 12.686, 0.001);
  EXPECT_NEAR(l.a_acc_mm_s2, 125, 1e-12);
  EXPECT_NEAR(l.a_dec_mm_s2, 125, 1e-12);
  // Against the fillet of the same corner (r = 0.01 / (sqrt 2 - 1)):
  // sqrt(sqrt(2970^2 - 625^2) r) = 8.37 mm/s.
  EXPECT_GT(l.v_max_mm_s, 1.5 * std::sqrt(std::sqrt(2970.0 * 2970 - 625.0 * 625) * 0.01 / (std::sqrt(2.0) - 1)));
}

// Turned by 45 degrees only X reverses (by sqrt 2 v instead of v): the
// same corner runs sqrt(sqrt 2) slower, per axis, not by a disc.
TEST(ParabolaLimits, DiagonalRightAngleLoadsOneAxisOnly) {
  const Mill m;
  const double h = 5 / std::sqrt(2.0);
  const motion::CornerBlend cb = corner(0, 0, h, h, 0, 2 * h, 0.01);
  const double leg = 0.04 / std::sqrt(2.0);
  const motion::PathLimits l = parabola_limits(cb.corner, m.dyn());
  EXPECT_NEAR(l.v_max_mm_s, std::sqrt(2 * leg * (0.99 * 3000 - 0.05 * 2500) / std::sqrt(2.0)), 1e-6);
}

// Passing out of the right angle onto the Y line: Y carries half the
// parabola's acceleration (+v^2 / (4 L)); what is left of 99 % of a_max
// for speeding up or braking along Y, less the crossing chord's lean.
TEST(ParabolaLimits, PassingOnTakesWhatHalfTheTurnLeavesPerAxis) {
  const Mill m;
  const motion::CornerBlend cb = corner(0, 0, 5, 0, 5, 5, 0.01);
  const motion::PathLimits l = parabola_limits(cb.corner, m.dyn());
  motion::PathLimits after{500, 2500, 2500};
  const double a = parabola_pass_acceleration(cb.corner, l, cb.after, after, true, m.dyn(), 0.001);
  const double half_turn = 0.5 * (0.99 * 3000 - 0.05 * 2500);
  EXPECT_LT(a, 0.99 * 3000 - half_turn);
  // The crossing chord: v (1 - cos e + theta^2 / 24) / dt = 214 mm/s^2 at
  // e = sqrt 2 half_turn dt / v, theta = 2 sqrt 2 half_turn dt / v.
  EXPECT_NEAR(a, 0.99 * 3000 - half_turn - 214, 2);
  // Into it from the X line: the same by symmetry.
  motion::PathLimits before{500, 2500, 2500};
  EXPECT_NEAR(parabola_pass_acceleration(cb.corner, l, cb.before, before, false, m.dyn(), 0.001), a, 1e-9);
}

}  // namespace
}  // namespace nck::prep
