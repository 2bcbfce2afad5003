// The per-cycle laws of the spindle-path couplings (feed_link.hpp), by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "nck/kernel/feed_link.hpp"

namespace nck::kernel {
namespace {

TEST(FeedLink, PathVelocityIsSpeedTimesFeedPerRevolution) {
  // G95 F0.2 at 1000 rpm: 200 mm/min = 3.333 mm/s.
  EXPECT_NEAR(link_velocity_mm_s(1000, 0.2), 200.0 / 60.0, 1e-12);
  // Seed 2.8.6: S200 x pitch 1.25 = F250 mm/min.
  EXPECT_NEAR(link_velocity_mm_s(200, 1.25) * 60.0, 250.0, 1e-9);
  // M4 (negative speed) feeds the same way; no pitch or NaN: no motion.
  EXPECT_NEAR(link_velocity_mm_s(-400, 1.5), 10.0, 1e-12);
  EXPECT_EQ(link_velocity_mm_s(400, 0), 0.0);
  EXPECT_EQ(link_velocity_mm_s(NAN, 1.5), 0.0);
}

TEST(FeedLink, ConstantCuttingSpeedFollowsTheRadius) {
  // v = 200 m/min at r = 50 mm: n = 200000 / (2 pi 50) = 636.62 rpm.
  EXPECT_NEAR(css_speed_rpm(200, 50, 0, 0), 200000.0 / (2 * std::numbers::pi * 50), 1e-9);
  EXPECT_NEAR(css_speed_rpm(200, 50, 0, 0), 636.6198, 1e-4);
  // Half the radius, twice the speed; the side of the centre does not matter.
  EXPECT_NEAR(css_speed_rpm(200, -25, 0, 0), 1273.2395, 1e-4);
  // G196 S1000 caps it near the centre, the gear stage's max_speed_mm_s below that.
  EXPECT_EQ(css_speed_rpm(200, 25, 1000, 0), 1000.0);
  EXPECT_EQ(css_speed_rpm(200, 25, 1000, 800), 800.0);
  EXPECT_EQ(css_speed_rpm(200, 0, 1000, 2500), 1000.0);  // at the centre: the limit, not a division by 0
  EXPECT_EQ(css_speed_rpm(200, 0, 0, 0), 0.0);            // no limit at all: nothing sensible
  EXPECT_TRUE(css_limited(200, 25, 1000, 0));
  EXPECT_FALSE(css_limited(200, 50, 1000, 0));
}

TEST(FeedLink, TappingAngleIsPathOverPitch) {
  // 50 mm at pitch 1.25: 40 turns = 14400 deg; negative S turns back.
  EXPECT_NEAR(tap_angle_deg(0, 50, 1.25, 1), 14400.0, 1e-9);
  EXPECT_NEAR(tap_angle_deg(180, 1.5, 1.5, -1), -180.0, 1e-9);
  EXPECT_EQ(tap_angle_deg(90, 10, 0, 1), 90.0);
}

TEST(FeedLink, StartAnglePassedInTheDirectionOfTurning) {
  EXPECT_TRUE(passes_angle(358, 4, 0));     // over the zero mark
  EXPECT_FALSE(passes_angle(2, 4, 0));      // already past it
  EXPECT_TRUE(passes_angle(178, 2.4, 180)); // S.OFFSET=180
  EXPECT_FALSE(passes_angle(175, 2.4, 180));
  EXPECT_TRUE(passes_angle(2, -4, 0));      // M4: turning backwards
  EXPECT_FALSE(passes_angle(358, -4, 0));
  EXPECT_TRUE(passes_angle(10, 400, 5));    // more than a turn in one cycle
  EXPECT_FALSE(passes_angle(180, 0, 180));  // standing on it is not passing it
}

}  // namespace
}  // namespace nck::kernel
