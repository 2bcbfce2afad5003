// The simulated spindle drive (sim::SpindleDrive) behind the spindle
// interpolator, stepped as the kernel steps it: command out after the set
// point, measured values back into the same cycle's status.
#include <gtest/gtest.h>

#include "../spindle/spindle_test_util.hpp"
#include "nck/sim/spindle_drive.hpp"
#include "nck/sim/spindle_drives.hpp"

namespace nck::sim {
namespace {

using spindle::SpindleAxis;
using spindle::SpindleMode;
using spindle::SpindleStatus;
using spindle::test::channel_spindle;
using spindle::test::spindle_axis_config;

// A spindle interpolator with its simulated drive.
struct DrivenSpindle {
  explicit DrivenSpindle(const config::AxisConfig& ax, const config::SimConfig& sim = {})
      : drive(SpindleDriveConfig::from(&ax, sim, 0.001)) {
    EXPECT_TRUE(s.configure(&ax, channel_spindle(), 0.001).has_value());
  }
  void tick() {
    if (s.tick(0.001)) s.take_feedback(drive.step(s.drive_command()));
  }
  void ticks(int n) {
    for (int i = 0; i < n; ++i) tick();
  }
  template <class Done>
  int run_until(Done done, int max_ticks) {
    for (int i = 0; i < max_ticks; ++i) {
      if (done(s.status())) return i;
      tick();
    }
    return max_ticks;
  }
  const SpindleStatus& status() const { return s.status(); }

  SpindleAxis s;
  SpindleDrive drive;
};

bool reached(const SpindleStatus& st) { return st.speed_reached && st.set_rpm == st.cmd_rpm; }

TEST(SpindleDrive, LagIsVOverKvAndFeedforwardRemovesIt) {
  DrivenSpindle d(spindle_axis_config());  // kv 10 1/s
  d.s.rotate(100);                         // 600 deg/s -> lag 60 deg
  d.run_until(reached, 20000);
  d.ticks(2000);
  EXPECT_NEAR(d.status().lag_deg, 60, 0.01);
  EXPECT_NEAR(d.drive.lag_deg(), 60, 0.01);
  EXPECT_NEAR(d.status().act_rpm, 100, 1e-6);
  d.s.feedforward_on();
  d.ticks(2000);
  EXPECT_NEAR(d.status().lag_deg, 0, 1e-3);
  d.s.feedforward_weight_pct(50);  // half the feedforward: half the lag
  d.ticks(2000);
  EXPECT_NEAR(d.status().lag_deg, 30, 0.01);
}

TEST(SpindleDrive, FeedforwardLagUnderAccelerationIsATaOverKv) {
  auto ax = spindle_axis_config();
  ax.feedforward_ta_s = 0.01;
  for (auto& g : ax.gears) {
    g.accel_mm_s2 = 3000;
    g.max_speed_mm_s = 1e6;
  }
  DrivenSpindle d(ax);
  d.s.feedforward_on();
  d.s.rotate(5000);  // 30000 deg/s needs 10 s at 3000 deg/s^2
  d.ticks(3000);
  EXPECT_NEAR(d.status().lag_deg, 3000 * 0.01 / 10, 1e-3);  // a*Ta/kv = 3 deg
}

// A stopped spindle's drive settles to exactly zero lag and speed in finite
// time (then its cycle is skipped), and stays exactly there.
TEST(SpindleDrive, StoppedDriveSettlesToExactlyZero) {
  DrivenSpindle d(spindle_axis_config());
  ASSERT_TRUE(d.s.rotate(1000).ok());
  d.run_until(reached, 20000);
  ASSERT_TRUE(d.s.stop().ok());
  const int settled =
      d.run_until([](const SpindleStatus& st) { return st.set_rpm == 0 && st.act_rpm == 0 && st.lag_deg == 0; }, 20000);
  EXPECT_LT(settled, 20000);
  const double pos_deg = d.status().set_pos_deg;
  d.ticks(1000);
  EXPECT_EQ(d.status().act_rpm, 0.0);
  EXPECT_EQ(d.status().lag_deg, 0.0);
  EXPECT_EQ(d.drive.lag_deg(), 0.0);
  EXPECT_EQ(d.status().set_pos_deg, pos_deg);
  EXPECT_TRUE(d.status().standstill);
  // ... and starts again from rest as before.
  ASSERT_TRUE(d.s.rotate(600).ok());
  d.run_until(reached, 20000);
  EXPECT_DOUBLE_EQ(d.status().set_rpm, 600);
}

// Speed-controlled: the actual speed follows the set speed with the drive's
// time constant (sim.lis drive.speed_time_constant_ms, 20 ms here).
TEST(SpindleDrive, SpeedControlledActualFollowsWithTheTimeConstant) {
  auto ax = spindle_axis_config();
  ax.drive_mode = config::DriveMode::open_loop;
  config::SimConfig sim;
  sim.drive_speed_time_constant_s = 0.02;
  DrivenSpindle d(ax, sim);
  ASSERT_TRUE(d.s.rotate(3000).ok());
  d.run_until([](const SpindleStatus& st) { return st.set_rpm == 3000; }, 20000);
  EXPECT_LT(d.status().act_rpm, 3000 - 1);  // still behind
  d.ticks(200);                             // 10 time constants
  EXPECT_NEAR(d.status().act_rpm, 3000, 0.01);
  EXPECT_TRUE(d.status().speed_reached);
}

// A reversed gear stage (getriebe[i].reverse): the drive turns the other
// way, the NC still sees its own sense.
TEST(SpindleDrive, ReverseFlipsCommandAndMeasuredValues) {
  auto ax = spindle_axis_config();
  for (auto& g : ax.gears) g.reverse_sense = true;
  DrivenSpindle d(ax);
  ASSERT_TRUE(d.s.rotate(100).ok());
  d.run_until(reached, 20000);
  d.ticks(2000);
  EXPECT_LT(d.s.drive_command().step_deg, 0);
  EXPECT_NEAR(d.drive.lag_deg(), -60, 0.01);
  EXPECT_NEAR(d.status().lag_deg, 60, 0.01);
  EXPECT_NEAR(d.status().act_rpm, 100, 1e-6);
}

// One drive per kernel spindle, in the kernel's order; an index beyond
// them measures nothing.
TEST(SpindleDrive, SetHasOneDrivePerMachineSpindle) {
  config::Machine m;
  m.axes.push_back(spindle_axis_config());
  config::ChannelConfig ch;
  config::ChannelSpindle sp = channel_spindle();
  sp.axis_index = 0;
  ch.spindles.push_back(sp);
  m.channels.push_back(ch);
  m.channel_data.emplace_back();
  SpindleDrives drives(m);
  EXPECT_EQ(drives.count(), 1u);
  EXPECT_TRUE(drives.step(0, spindle::DriveCommand{0.6, 0.6, 0, 1}).valid);
  EXPECT_FALSE(drives.step(1, spindle::DriveCommand{}).valid);
}

}  // namespace
}  // namespace nck::sim
