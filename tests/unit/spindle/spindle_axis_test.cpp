// The spindle interpolator against the seed's behaviour (FCT-S1 2.3-2.8).
#include <gtest/gtest.h>

#include <cmath>

#include "spindle_test_util.hpp"

namespace nck::spindle {
namespace {

using test::make_spindle;
using test::run_until;
using test::spindle_axis_config;

bool reached(const SpindleStatus& st) { return st.speed_reached && st.set_rpm == st.cmd_rpm; }

TEST(SpindleAxis, ConfigureRejectsBadCycle) {
  SpindleAxis s;
  auto ax = spindle_axis_config();
  EXPECT_FALSE(s.configure(&ax, test::channel_spindle(), 0).has_value());
  EXPECT_EQ(s.rotate(100).id, ErrorId::SpindleNotConfigured);
  s.tick(0.001);  // harmless
}

TEST(SpindleAxis, RampUsesABeschlUpAndABremsDown) {
  auto s = make_spindle(spindle_axis_config());
  ASSERT_TRUE(s.rotate(1000).ok());  // 6000 deg/s at accel_mm_s2 3000 -> 2 s
  const int up = run_until(s, [](const SpindleStatus& st) { return st.set_rpm >= 1000; }, 10000);
  EXPECT_NEAR(up, 2000, 2);
  EXPECT_EQ(s.status().mode, SpindleMode::rotate);
  ASSERT_TRUE(s.stop().ok());  // decel_mm_s2 4000 -> 1.5 s
  const int down = run_until(s, [](const SpindleStatus& st) { return st.set_rpm == 0; }, 10000);
  EXPECT_NEAR(down, 1500, 2);
  run_until(s, [](const SpindleStatus& st) { return st.standstill; }, 5000);
  EXPECT_TRUE(s.status().standstill);
  EXPECT_TRUE(s.status().speed_reached);  // M5 waits for standstill
}

TEST(SpindleAxis, OverrideExampleWithG167) {
  // 2.4.1: N10 S2[M3 REV1000] at 50 % -> 500; N20 S2[G167] -> 1000;
  // N30 S2[REV3000] -> override active again -> 1500.
  auto s = make_spindle(spindle_axis_config());
  s.set_override_pct(50);
  ASSERT_TRUE(s.rotate(1000).ok());
  run_until(s, reached, 20000);
  EXPECT_DOUBLE_EQ(s.status().set_rpm, 500);
  s.suppress_override();
  run_until(s, reached, 20000);
  EXPECT_DOUBLE_EQ(s.status().set_rpm, 1000);
  ASSERT_TRUE(s.rotate(3000).ok());
  run_until(s, reached, 20000);
  EXPECT_DOUBLE_EQ(s.status().set_rpm, 1500);
  // G167 together with a speed: that speed ignores the override.
  ASSERT_TRUE(s.rotate(2000, true).ok());
  run_until(s, reached, 20000);
  EXPECT_DOUBLE_EQ(s.status().set_rpm, 2000);
}

TEST(SpindleAxis, SpeedReachedUsesTheVbProzentBand) {
  auto ax = spindle_axis_config();
  ax.speed_reached_tolerance_permille = 100;  // +-10 %
  auto s = make_spindle(ax);
  ASSERT_TRUE(s.rotate(1000).ok());
  // Speed reached switches on once the actual speed is within 900..1100 rpm.
  run_until(s, [](const SpindleStatus& st) { return st.speed_reached; }, 10000);
  EXPECT_GE(s.status().act_rpm, 900);
  EXPECT_LT(s.status().act_rpm, 905);  // it switched at the band edge, not later
  EXPECT_EQ(s.status().mode, SpindleMode::rotate);
}

TEST(SpindleAxis, SpeedIsLimitedByVbMax) {
  auto s = make_spindle(spindle_axis_config());
  auto r = s.rotate(20000);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.id, ErrorId::SpindleSpeedLimited);
  run_until(s, reached, 100000);
  EXPECT_DOUBLE_EQ(s.status().set_rpm, 10000);
}

TEST(SpindleAxis, M4ReversesThroughStandstill) {
  auto s = make_spindle(spindle_axis_config());
  s.rotate(500);
  run_until(s, reached, 20000);
  s.rotate(-500);
  double prev = s.status().set_rpm;
  bool saw_zero = false;
  for (int i = 0; i < 5000; ++i) {
    s.tick(0.001);
    const double v = s.status().set_rpm;
    if (v == 0) saw_zero = true;
    EXPECT_FALSE(prev > 0 && v < 0) << "jumped over standstill";
    prev = v;
  }
  EXPECT_TRUE(saw_zero);
  EXPECT_DOUBLE_EQ(s.status().set_rpm, -500);
}

TEST(SpindleAxis, M19FromStandstillHomesThenPositionsShortestWay) {
  auto s = make_spindle(spindle_axis_config());
  EXPECT_FALSE(s.status().homed);
  ASSERT_TRUE(s.position(300, Direction::none, 100).ok());
  EXPECT_EQ(s.status().mode, SpindleMode::homing);  // no reference yet: home first
  run_until(s, [](const SpindleStatus& st) { return st.in_position; }, 60000);
  EXPECT_TRUE(s.status().in_position);
  EXPECT_TRUE(s.status().homed);
  EXPECT_EQ(s.status().mode, SpindleMode::position);
  EXPECT_NEAR(s.status().set_pos_deg, 300, 1e-9);
  EXPECT_DOUBLE_EQ(s.status().set_rpm, 0);
  // Homed now: M19 to 250 from 300 takes the short way (negative).
  ASSERT_TRUE(s.position(250, Direction::none, 100).ok());
  EXPECT_EQ(s.status().mode, SpindleMode::position);
  bool went_negative = false, went_positive = false;
  for (int i = 0; i < 20000 && !s.status().in_position; ++i) {
    s.tick(0.001);
    went_negative |= s.status().set_rpm < 0;
    went_positive |= s.status().set_rpm > 0;
  }
  EXPECT_TRUE(s.status().in_position);
  EXPECT_TRUE(went_negative);
  EXPECT_FALSE(went_positive);
  EXPECT_NEAR(s.status().set_pos_deg, 250, 1e-9);
}

TEST(SpindleAxis, M19FromRotationKeepsTheDirection) {
  auto s = make_spindle(spindle_axis_config());
  s.home();
  run_until(s, [](const SpindleStatus& st) { return st.mode == SpindleMode::stop && st.standstill; }, 60000);
  ASSERT_TRUE(s.status().homed);
  s.rotate(-300);
  run_until(s, reached, 20000);
  ASSERT_TRUE(s.position(90, Direction::none, 200).ok());
  bool went_positive = false;
  for (int i = 0; i < 20000 && !s.status().in_position; ++i) {
    s.tick(0.001);
    went_positive |= s.status().set_rpm > 0;
  }
  EXPECT_TRUE(s.status().in_position);
  EXPECT_FALSE(went_positive);
  EXPECT_NEAR(s.status().set_pos_deg, 90, 1e-9);
}

TEST(SpindleAxis, HomingG74SetsReferenceAndPositionsToPosRefpkt) {
  auto ax = spindle_axis_config();
  for (auto& g : ax.gears) g.reference_pos = 45;
  auto s = make_spindle(ax);
  // G74 does not block: the command returns at once and the spindle homes
  // in the following cycles while the channel goes on (seed examples 1-3).
  ASSERT_TRUE(s.home().ok());
  EXPECT_EQ(s.status().mode, SpindleMode::homing);
  EXPECT_FALSE(s.status().homed);
  const int ticks = run_until(
      s, [](const SpindleStatus& st) { return st.mode == SpindleMode::stop && st.standstill; }, 60000);
  EXPECT_LT(ticks, 60000);
  EXPECT_TRUE(s.status().homed);
  EXPECT_NEAR(s.status().set_pos_deg, 45, 1e-9);
  EXPECT_LE(std::fabs(s.status().set_rpm), 0);
}

TEST(SpindleAxis, ControlLimitLosesReferenceAndM5HomesOnTheWayDown) {
  auto ax = spindle_axis_config();
  for (auto& g : ax.gears) g.control_limit_deg_s = 1200;  // 200 rpm
  auto s = make_spindle(ax);
  s.home();
  run_until(s, [](const SpindleStatus& st) { return st.mode == SpindleMode::stop && st.standstill; }, 60000);
  ASSERT_TRUE(s.status().homed);
  s.rotate(150);  // below the limit: reference kept
  run_until(s, reached, 20000);
  EXPECT_TRUE(s.status().homed);
  s.rotate(1000);
  run_until(s, reached, 20000);
  EXPECT_FALSE(s.status().homed);
  EXPECT_TRUE(s.status().reference_lost);
  ASSERT_TRUE(s.stop().ok());
  EXPECT_EQ(s.status().mode, SpindleMode::homing);
  run_until(s, [](const SpindleStatus& st) { return st.mode == SpindleMode::stop && st.standstill; }, 60000);
  EXPECT_TRUE(s.status().homed);
  EXPECT_FALSE(s.status().reference_lost);
}

TEST(SpindleAxis, PreferredDirectionErrorAndReset) {
  auto ax = spindle_axis_config();
  ax.has_preferred_direction = true;
  ax.preferred_direction_positive = true;
  auto s = make_spindle(ax);
  EXPECT_TRUE(s.rotate(100).ok());
  auto r = s.rotate(-100);
  EXPECT_EQ(number(r.id), 60254u);
  EXPECT_EQ(s.status().mode, SpindleMode::error);
  EXPECT_EQ(number(s.status().error), 60254u);
  EXPECT_EQ(s.rotate(100).id, ErrorId::SpindleInErrorState);
  s.reset();
  EXPECT_EQ(s.status().mode, SpindleMode::stop);
  EXPECT_TRUE(s.rotate(100).ok());
  EXPECT_EQ(number(s.position(10, Direction::negative, 50).id), 60254u);
}

TEST(SpindleAxis, SensorlessSpindleCannotPosition70252) {
  auto ax = spindle_axis_config();
  ax.drive_mode = config::DriveMode::open_loop;
  ax.speed_time_base = 0;
  ax.speed_increments_num = 32767;
  ax.speed_increments_denom = 1080000000;
  auto s = make_spindle(ax);
  EXPECT_EQ(number(s.position(90, Direction::none, 100).id), 70252u);
  EXPECT_EQ(number(s.home().id), 70252u);
  EXPECT_EQ(s.status().mode, SpindleMode::stop);
  ASSERT_TRUE(s.rotate(3000).ok());
  run_until(s, [](const SpindleStatus& st) { return st.set_rpm == 3000; }, 20000);
  EXPECT_NEAR(s.status().drive_output, 32767, 1e-6);  // seed 2.2.4.1
  // The actual speed follows with the drive time constant (20 ms).
  for (int i = 0; i < 200; ++i) s.tick(0.001);
  EXPECT_NEAR(s.status().act_rpm, 3000, 0.01);
  EXPECT_TRUE(s.status().speed_reached);
}

TEST(SpindleAxis, GearChangeApproachesChangePositionThenTakesNewData) {
  auto ax = spindle_axis_config();
  ax.gears[0].gear_change_pos_deg = 120;
  ax.gears[1].accel_mm_s2 = 600;  // stage 2 accelerates slower
  auto s = make_spindle(ax);
  s.home();
  run_until(s, [](const SpindleStatus& st) { return st.mode == SpindleMode::stop && st.standstill; }, 60000);
  s.rotate(200);
  run_until(s, reached, 20000);
  EXPECT_EQ(s.finish_gear_change().id, ErrorId::SpindleGearChangeState);
  ASSERT_TRUE(s.start_gear_change(2).ok());
  EXPECT_EQ(s.status().mode, SpindleMode::gear_change);
  double max_rpm_after_slowdown = 0;
  int ticks = 0;
  for (; ticks < 60000 && !s.status().gear_change_ready; ++ticks) {
    s.tick(0.001);
    if (ticks > 2000) max_rpm_after_slowdown = std::max(max_rpm_after_slowdown, std::fabs(s.status().set_rpm));
  }
  ASSERT_TRUE(s.status().gear_change_ready);
  EXPECT_LE(max_rpm_after_slowdown, 100 + 1e-9);  // rapid_mm_s 600 deg/s
  EXPECT_NEAR(s.status().set_pos_deg, 120, 1e-9);
  EXPECT_EQ(s.status().gear_stage, 1u);
  ASSERT_TRUE(s.finish_gear_change().ok());
  EXPECT_EQ(s.status().gear_stage, 2u);
  EXPECT_EQ(s.status().mode, SpindleMode::stop);
  s.rotate(100);  // 600 deg/s at 600 deg/s^2 -> 1 s
  const int up = run_until(s, [](const SpindleStatus& st) { return st.set_rpm >= 100; }, 10000);
  EXPECT_NEAR(up, 1000, 2);
}

TEST(SpindleAxis, ToolDynamicsTakeEffectFromStandstill) {
  auto s = make_spindle(spindle_axis_config());
  s.rotate(1000);
  run_until(s, reached, 20000);
  s.set_tool_dynamics(ToolDynamics{0, 500, 1000});
  s.rotate(1000);  // still turning: old limits
  run_until(s, reached, 20000);
  EXPECT_DOUBLE_EQ(s.status().set_rpm, 1000);
  s.stop();
  run_until(s, [](const SpindleStatus& st) { return st.standstill; }, 20000);
  s.rotate(1000);  // from standstill: tool limits now, 500 rpm at 1000 deg/s^2
  const int up = run_until(s, reached, 20000);
  EXPECT_DOUBLE_EQ(s.status().set_rpm, 500);
  EXPECT_NEAR(up, 3000, 3);
  s.stop();
  run_until(s, [](const SpindleStatus& st) { return st.standstill; }, 20000);
  ASSERT_TRUE(s.default_dynamic_data().ok());
  s.rotate(1000);
  run_until(s, reached, 20000);
  EXPECT_DOUBLE_EQ(s.status().set_rpm, 1000);
  EXPECT_EQ(s.default_dynamic_data().id, ErrorId::SpindleNotAtStandstill);
}

TEST(SpindleAxis, G130WeightsTheAcceleration) {
  auto s = make_spindle(spindle_axis_config());
  ASSERT_TRUE(s.set_accel_weight_pct(50).ok());  // 1500 deg/s^2
  s.rotate(250);
  const int up = run_until(s, [](const SpindleStatus& st) { return st.set_rpm >= 250; }, 10000);
  EXPECT_NEAR(up, 1000, 2);
  EXPECT_FALSE(s.set_accel_weight_pct(-5).ok());
}

TEST(SpindleAxis, FeedholdStopsAndResumes) {
  auto s = make_spindle(spindle_axis_config());
  s.rotate(300);
  run_until(s, reached, 20000);
  s.set_feedhold(true);
  run_until(s, [](const SpindleStatus& st) { return st.standstill; }, 20000);
  EXPECT_EQ(s.status().mode, SpindleMode::rotate);
  EXPECT_FALSE(s.status().speed_reached);
  s.set_feedhold(false);
  run_until(s, reached, 20000);
  EXPECT_DOUBLE_EQ(s.status().set_rpm, 300);
}

TEST(SpindleAxis, ResetStopsUnlessConfiguredToKeepTurning) {
  auto ax = spindle_axis_config();
  auto s = make_spindle(ax);
  s.rotate(300);
  run_until(s, reached, 20000);
  s.reset();
  EXPECT_EQ(s.status().mode, SpindleMode::stop);
  ax.no_stop_by_channel_reset = true;
  auto k = make_spindle(ax);
  k.rotate(300);
  run_until(k, reached, 20000);
  k.reset();
  EXPECT_EQ(k.status().mode, SpindleMode::rotate);
  for (int i = 0; i < 100; ++i) k.tick(0.001);
  EXPECT_DOUBLE_EQ(k.status().set_rpm, 300);
}

TEST(SpindleAxis, AxisModeNeedsStandstillAndFollowsThePath) {
  auto s = make_spindle(spindle_axis_config());
  s.rotate(100);
  s.tick(0.001);
  EXPECT_EQ(s.enter_axis_mode().id, ErrorId::SpindleNotAtStandstill);
  s.stop();
  run_until(s, [](const SpindleStatus& st) { return st.standstill; }, 20000);
  ASSERT_TRUE(s.enter_axis_mode().ok());
  EXPECT_EQ(s.rotate(100).id, ErrorId::SpindleAxisMode);
  const double start = s.status().set_pos_deg;
  s.axis_set_point(start + 10, 10000);
  s.tick(0.001);
  EXPECT_NEAR(s.status().set_pos_deg, wrap_modulo(start + 10, 0, 360), 1e-9);
  s.axis_set_point(start + 10, 0);
  s.tick(0.001);
  ASSERT_TRUE(s.leave_axis_mode().ok());
  EXPECT_EQ(s.status().mode, SpindleMode::stop);
}

TEST(SpindleAxis, BadValuesAreRejected) {
  auto s = make_spindle(spindle_axis_config());
  EXPECT_EQ(s.rotate(std::nan("")).id, ErrorId::SpindleBadValue);
  EXPECT_EQ(s.position(std::nan(""), Direction::none, 100).id, ErrorId::SpindleBadValue);
  EXPECT_EQ(s.position(10, Direction::none, 0).id, ErrorId::SpindleBadValue);
  EXPECT_EQ(s.start_gear_change(7).id, ErrorId::SpindleGearStageInvalid);
  s.set_override_pct(std::nan(""));
  s.tick(std::nan(""));
  s.tick(-1);
  EXPECT_DOUBLE_EQ(s.status().override_pct, 100);
  EXPECT_TRUE(std::isfinite(s.status().set_pos_deg));
}

TEST(SpindleAxis, PlcSpindleWithoutAxisListRuns) {
  SpindleAxis s;
  auto sp = test::channel_spindle();
  sp.plc_control = true;
  ASSERT_TRUE(s.configure(nullptr, sp, 0.001).has_value());
  s.rotate(20);  // default gear data: max_speed_mm_s 200 deg/s
  run_until(s, reached, 20000);
  EXPECT_NEAR(s.status().set_rpm, 20, 1e-9);
}

}  // namespace
}  // namespace nck::spindle
