// A conventional drive (kenngr.antr_typ 1) takes a velocity set point and
// the NC closes the position loop: vel = the set point's velocity + kv x
// the following error of the last set point. Here the drive's velocity
// scaling is 10 % off: without the loop the axis would end 10 % short.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "test_machine.hpp"

namespace nck::kernel {
namespace {

using testing::KernelRig;
using testing::move;
using testing::xyz_machine;

constexpr double kKv = 20;  // 1/s

config::Machine conventional_machine() {
  config::Machine m = xyz_machine(500, 2000);
  for (auto& ax : m.axes) {
    ax.drive_type = 1;
    for (auto& g : ax.gears) g.position_gain_1_s = kKv;
  }
  return m;
}

struct Outcome {
  double end_fb_mm = 0;
  double worst_error_mm = 0;
  double first_vel_mm_s = 0;  // X's velocity set point in the cycle after the first move began
};

Outcome run(bool powered) {
  KernelRig rig(conventional_machine());
  rig.push_block(0, move(10, nc::Motion::linear, 100.0));
  rig.push_block(0, testing::end_block(20));
  auto in = std::make_unique<TickInput>();
  auto out = std::make_unique<TickOutput>();
  in->machine.machine_on = powered;
  Outcome r;
  double fb = 0;
  for (int i = 0; i < 5000; ++i) {
    in->drives[0].actual_pos = fb;
    rig.k.tick(*in, *out);
    const drives::DriveCommand& cmd = out->drives[0];
    if (r.first_vel_mm_s == 0 && cmd.target_vel != 0) r.first_vel_mm_s = cmd.target_vel;
    r.worst_error_mm = std::max(r.worst_error_mm, std::fabs(cmd.target_pos - fb));
    fb += 0.9 * cmd.target_vel * 0.001;  // the drive: 10 % slow
  }
  r.end_fb_mm = fb;
  return r;
}

TEST(ConventionalDrive, KvLoopBringsASlowDriveToItsSetPoint) {
  const Outcome r = run(true);
  EXPECT_NEAR(r.end_fb_mm, 100.0, 1e-6);
  EXPECT_LT(r.worst_error_mm, 2.0);
}

TEST(ConventionalDrive, NoVelocityWhileTheMachineIsOff) {
  const Outcome r = run(false);
  EXPECT_EQ(r.first_vel_mm_s, 0.0);
  EXPECT_EQ(r.end_fb_mm, 0.0);
}

// A spindle on a conventional drive (an analogue VFD with an encoder): the
// drive turns at its velocity set point, 10 % slow, and the NC measures its
// speed and position (TickInput::spindle_measured, as HAL's speed-in and
// revs). While it turns (M3) the drive controls its speed: the set point
// is the programmed speed alone. For M19 the NC closes the position loop
// with kv: S1 stands at 90 deg in position. Without the loop the drive
// would stop short and M19 would never end.
struct VfdSpindle {
  VfdSpindle() : rig(machine()) {}
  static config::Machine machine() {
    config::Machine m = xyz_machine(100, 100000);
    config::AxisConfig& s1 = testing::add_spindle_s1(m);
    s1.drive_type = 1;
    s1.drive_mode = config::DriveMode::open_loop_pos_feedback;  // speed-controlled, knows its position
    for (auto& g : s1.gears) g.position_gain_1_s = kKv;
    return m;
  }
  void run(int cycles) {
    for (int i = 0; i < cycles && !rig.k.all_channels_done(); ++i) {
      in->spindle_measured[0] = {0.9 * vel_deg_s, pos_deg, true};
      rig.k.tick(*in, *out);
      vel_deg_s = out->drives[kS1].target_vel;
      pos_deg += 0.9 * vel_deg_s * 0.001;
    }
  }
  static constexpr std::size_t kS1 = 3;  // S1's axis list (after X, Y, Z)
  KernelRig rig;
  std::unique_ptr<TickInput> in = std::make_unique<TickInput>();
  std::unique_ptr<TickOutput> out = std::make_unique<TickOutput>();
  double vel_deg_s = 0, pos_deg = 0;
};

TEST(ConventionalDrive, SpindleTurnsOnItsSpeedAndPositionsWithTheKvLoop) {
  VfdSpindle d;
  d.rig.push_block(0, testing::spindle_block(1, nc::SpindleM::m3, 600.0));
  d.run(1000);
  EXPECT_NEAR(d.vel_deg_s, 3600.0, 1e-9);  // 600 rpm: the drive's own speed loop, no position term
  d.rig.push_block(0, testing::spindle_block(2, nc::SpindleM::m19, 400.0, 90.0));
  d.rig.push_block(0, testing::end_block(3));
  d.run(20000);
  ASSERT_TRUE(d.rig.k.all_channels_done());
  const spindle::SpindleStatus& s = d.rig.k.spindle_status(0);
  EXPECT_TRUE(s.in_position);
  EXPECT_NEAR(s.act_pos_deg, 90.0, 0.01);
  const double turns = d.pos_deg / 360.0;
  EXPECT_NEAR((turns - std::floor(turns)) * 360.0, 90.0, 0.01);
}

}  // namespace
}  // namespace nck::kernel
