// Seed FCT-S1 2.2.4.1 / 2.2.4.2: speed scaling of speed-controlled spindles.
#include <gtest/gtest.h>

#include <cmath>

#include "nck/spindle/drive_scaling.hpp"

namespace nck::spindle {
namespace {

TEST(DriveScaling, SensorlessExample3000RpmIs32767) {
  config::AxisConfig ax;
  ax.speed_time_base = 0;
  ax.speed_increments_num = 32767;
  ax.speed_increments_denom = 1080000000;
  EXPECT_NEAR(drive_output_value(ax, 3000, 0.001), 32767, 1e-6);
  EXPECT_NEAR(drive_output_value(ax, -3000, 0.001), -32767, 1e-6);
  EXPECT_NEAR(drive_output_value(ax, 1500, 0.001), 16383.5, 1e-6);
}

TEST(DriveScaling, SpeedFeedbackExample1RpmIs1) {
  config::AxisConfig ax;
  ax.speed_time_base = 0;
  ax.speed_increments_num = 1;
  ax.speed_increments_denom = 360000;
  EXPECT_NEAR(drive_output_value(ax, 1, 0.001), 1, 1e-12);
  EXPECT_NEAR(drive_output_value(ax, 2500, 0.001), 2500, 1e-9);
}

TEST(DriveScaling, TimeBasesAndBadScaling) {
  // 60 rpm = 360 deg/s = 360000 mdeg/s.
  EXPECT_NEAR(drive_output_value(1, 1000, 1, 60, 0.001), 360, 1e-9);       // per second
  EXPECT_NEAR(drive_output_value(1, 1000, 2, 60, 0.002), 0.72, 1e-12);     // per 2 ms cycle
  EXPECT_EQ(drive_output_value(1, 0, 0, 60, 0.001), 0);
  EXPECT_EQ(drive_output_value(1, 1, 7, 60, 0.001), 0);
  EXPECT_EQ(drive_output_value(1, 1, 0, std::nan(""), 0.001), 0);
}

}  // namespace
}  // namespace nck::spindle
