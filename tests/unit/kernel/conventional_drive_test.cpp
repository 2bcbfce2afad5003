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

}  // namespace
}  // namespace nck::kernel
