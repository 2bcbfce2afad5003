// The per-cycle velocity limit of a spindle coupling (G95, G33, tapping):
// the profile ramps to it with its own accelerations and still ends exactly.
#include <gtest/gtest.h>

#include "nck/motion/path_profile.hpp"

namespace nck::motion {
namespace {

constexpr double kDt = 0.001;

TEST(PathVelocityLimit, CapsTheCommandedVelocityEachCycle) {
  PathProfile p;
  const PathLimits l{100.0, 500.0, 1000.0};
  ASSERT_TRUE(p.start(50.0, 100.0, l));
  // Limit 10 mm/s: after 10 mm/s / 500 mm/s^2 = 20 cycles it cruises at 10.
  ProfileSample s{};
  for (int k = 0; k < 100; ++k) {
    p.set_velocity_limit(10.0);
    s = p.step(kDt, 1.0);
  }
  EXPECT_DOUBLE_EQ(s.v_mm_s, 10.0);
  // The limit rises: the profile accelerates by a_acc * dt per cycle.
  p.set_velocity_limit(20.0);
  s = p.step(kDt, 1.0);
  EXPECT_NEAR(s.v_mm_s, 10.5, 1e-12);
  // Limit 0 holds the path with a_dec (1 mm/s per cycle).
  p.set_velocity_limit(0.0);
  s = p.step(kDt, 1.0);
  EXPECT_NEAR(s.v_mm_s, 9.5, 1e-12);
  // Cleared: back to v_cmd; the end is reached exactly.
  p.set_velocity_limit(-1.0);
  for (int k = 0; k < 100000 && !s.finished; ++k) s = p.step(kDt, 1.0);
  EXPECT_TRUE(s.finished);
  EXPECT_EQ(p.s(), 50.0);
}

TEST(PathVelocityLimit, StartClearsLimitAndOverrideIgnoredRunsAtFullSpeed) {
  PathProfile p;
  const PathLimits l{100.0, 1e6, 1e6};
  ASSERT_TRUE(p.start(100.0, 30.0, l));
  p.set_velocity_limit(5.0);
  p.set_override_ignored(true);
  EXPECT_DOUBLE_EQ(p.step(kDt, 0.5).v_mm_s, 5.0);  // the override does not act
  ASSERT_TRUE(p.start(100.0, 30.0, l));
  EXPECT_DOUBLE_EQ(p.step(kDt, 0.5).v_mm_s, 15.0);  // new segment: no limit, override acts
}

}  // namespace
}  // namespace nck::motion
