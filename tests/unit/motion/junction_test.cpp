// Corner and entry limits of the velocity look-ahead, checked by hand and
// against the profile that has to follow them.
#include "nck/motion/junction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "nck/motion/path_profile.hpp"

namespace nck::motion {
namespace {

AxisVector dir(double x, double y) {
  AxisVector v{};
  v[0] = x;
  v[1] = y;
  return v;
}

TEST(CornerVelocity, RightAngleIsLimitedByTheBudgetOfEachTurningAxis) {
  const std::vector<double> dv{0.5, 2.0};  // mm/s per cycle
  // X stops (turn 1) and Y starts (turn 1): X's budget of 0.5 decides.
  EXPECT_DOUBLE_EQ(corner_velocity(dir(1, 0), dir(0, 1), dv), 0.5);
  // A reversal turns X by 2.
  EXPECT_DOUBLE_EQ(corner_velocity(dir(1, 0), dir(-1, 0), dv), 0.25);
}

TEST(CornerVelocity, SmallKinkAtFullBudget) {
  // A 1 degree kink turns X by 1 - cos(1 deg) and Y by sin(1 deg).
  const double a = M_PI / 180;
  const std::vector<double> dv{0.5, 0.5};
  EXPECT_NEAR(corner_velocity(dir(1, 0), dir(std::cos(a), std::sin(a)), dv), 0.5 / std::sin(a), 1e-9);
}

TEST(CornerVelocity, StraightOrTangentIsNotLimitedAndNoBudgetMeansStop) {
  const std::vector<double> dv{0.5, 0.5};
  EXPECT_TRUE(std::isinf(corner_velocity(dir(0.6, 0.8), dir(0.6, 0.8), dv)));
  EXPECT_EQ(corner_velocity(dir(1, 0), dir(0, 1), std::vector<double>{0.0, 0.0}), 0.0);
  // An axis outside the budget list is not looked at.
  EXPECT_TRUE(std::isinf(corner_velocity(dir(1, 0), dir(0, 1), std::vector<double>{})));
}

// Entering a path at the limit, the profile reaches the exit velocity at
// the end, braking at no more than a per cycle.
TEST(EntryVelocityLimit, TheProfileFollowsItToTheExitVelocity) {
  const double dt = 0.001, a = 2500;
  for (double length : {0.05, 0.5, 3.0, 40.0}) {
    for (double v_exit : {0.0, 5.0, 20.0}) {
      const double v_in = entry_velocity_limit(length, v_exit, a, dt);
      ASSERT_GT(v_in, 0.0);
      // A profile that arrives at v_in: run one that starts from it.
      PathProfile feed_in, p;
      const PathLimits lim{1e6, a, a};
      ASSERT_TRUE(feed_in.start(1e6, v_in, lim, v_in));  // accelerate to v_in on a long way
      ProfileSample s{};
      while (feed_in.v() < v_in - 1e-9) s = feed_in.step(dt, 1.0);
      p = feed_in;
      ASSERT_TRUE(p.start(length, 1e6, lim, v_exit));
      double v_prev = v_in;
      do {
        s = p.step(dt, 1.0);
        EXPECT_LE(v_prev - s.v_mm_s, a * dt * (1 + 1e-9) + 1e-9) << length << " " << v_exit;
        v_prev = s.v_mm_s;
      } while (!s.finished);
      EXPECT_LE(s.v_mm_s, std::max(v_exit, 0.0) + a * dt + 1e-9) << length << " " << v_exit;
    }
  }
}

TEST(EntryVelocityLimit, GrowsWithLengthAndExitVelocity) {
  const double dt = 0.001, a = 2500;
  EXPECT_LT(entry_velocity_limit(1, 0, a, dt), entry_velocity_limit(2, 0, a, dt));
  EXPECT_LT(entry_velocity_limit(1, 0, a, dt), entry_velocity_limit(1, 10, a, dt));
  // Continuous limit sqrt(v^2 + 2 a L) within one braking step.
  EXPECT_NEAR(entry_velocity_limit(10, 0, a, dt), std::sqrt(2 * a * 10), a * dt);
}

}  // namespace
}  // namespace nck::motion
