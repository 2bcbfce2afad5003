// G33 starts on the spindle's zero mark (+ OFFSET), so that every pass
// meets the groove the first one cut. On a real machine the spindle's
// angle is what its encoder measures (TickInput::spindle_measured, HAL's
// revs), not the NC's set point: a VFD runs a little slow or lags, and the
// groove is where the spindle really was. Here the measured angle trails
// the set point by 45 deg: the thread must start when the *measured* angle
// passes 0.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "test_machine.hpp"

namespace nck::kernel {
namespace {

using testing::KernelRig;

constexpr double kTrailDeg = 45;

double wrapped(double deg) { return deg - 360.0 * std::floor(deg / 360.0); }

// S1 turning at 600 rpm (M3 S600) and a G33 pass of pitch 1 mm queued
// behind it; each cycle the test says what the spindle's encoder measured.
struct ThreadRig {
  static config::Machine machine() {
    config::Machine m = testing::xyz_machine(500, 5000);
    testing::add_spindle_s1(m);
    return m;
  }
  ThreadRig() : rig(machine()) {
    rig.push_block(0, testing::spindle_block(1, nc::SpindleM::m3, 600.0));
    nc::Block thread = testing::move(2, nc::Motion::thread, {}, {}, -10.0);
    thread.modal.thread_pitch_mm = 1.0;
    rig.push_block(0, thread);
  }
  // One cycle with this measurement; true once the thread's path moves.
  bool cycle(const spindle::DriveFeedback& measured) {
    in->spindle_measured[0] = measured;
    rig.k.tick(*in, *out);
    set_deg = out->spindles[0].set_pos_deg;  // the NC wraps what it measures
    vel_deg_s = out->spindles[0].set_rpm * 6.0;
    return out->channels[0].path_velocity_mm_s > 0;
  }
  KernelRig rig;
  std::unique_ptr<TickInput> in = std::make_unique<TickInput>();
  std::unique_ptr<TickOutput> out = std::make_unique<TickOutput>();
  double set_deg = 0, vel_deg_s = 0;  // the set point after the last cycle
};

// The measured angle (deg, in [0, 360)) in the cycle the thread's path began to move.
double measured_angle_at_thread_start(bool measured) {
  ThreadRig t;
  for (int i = 0; i < 20000; ++i)
    if (t.cycle({t.vel_deg_s, t.set_deg - kTrailDeg, measured})) return wrapped(t.set_deg - kTrailDeg);
  ADD_FAILURE() << "the thread never started";
  return -1;
}

TEST(ThreadSync, G33StartsOnTheMeasuredZeroMark) {
  const double step_deg = 600 * 6 * 0.001;  // the spindle turns 3.6 deg a cycle
  const double angle = measured_angle_at_thread_start(true);
  EXPECT_LT(std::min(angle, 360 - angle), 2 * step_deg) << "measured angle " << angle;
}

// Without a measured spindle the set point is the angle: the same start
// lies 45 deg behind on the (not measured) trailing angle.
TEST(ThreadSync, WithoutMeasuringTheSetPointIsTheAngle) {
  const double angle = measured_angle_at_thread_start(false);
  EXPECT_NEAR(angle, 360 - kTrailDeg, 2 * 3.6);
}

// An encoder that resets at its index (HAL's index-enable): while the
// reset is pending the angle is no reference, so G33 does not start even
// when it passes 0; the reset itself (the count back to 0) is the zero
// mark, and the thread starts in that cycle.
TEST(ThreadSync, G33WaitsForThePendingIndexResetAndStartsOnIt) {
  ThreadRig t;
  constexpr int kResetCycle = 1500;  // the index comes 1.5 s in (the spindle turned 9 turns)
  double reset_at_deg = 0;           // the encoder counts from here
  int started = -1;
  for (int i = 0; i < 5000 && started < 0; ++i) {
    if (i == kResetCycle) reset_at_deg = t.set_deg - 1.0;  // the index passed 1 deg ago: the count restarted there
    if (t.cycle({t.vel_deg_s, t.set_deg - reset_at_deg, true, i < kResetCycle})) started = i;
  }
  EXPECT_EQ(started, kResetCycle);
}

}  // namespace
}  // namespace nck::kernel
