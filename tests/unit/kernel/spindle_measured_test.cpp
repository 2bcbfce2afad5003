// The kernel judges its spindles from measured values that come in through
// TickInput::spindle_measured, as a real machine's drives deliver them, with
// no simulated drive attached: speed reached, standstill and the block that
// waits for the speed follow what was measured, not the set point.
#include <gtest/gtest.h>

#include <functional>

#include "nck/kernel/kernel.hpp"
#include "nck/spindle/positioning.hpp"
#include "test_machine.hpp"
#include "../seen_events.hpp"

namespace nck::kernel {
namespace {

using testing::end_block;
using testing::KernelRig;
using testing::add_spindle_s1;
using testing::move;
using testing::xyz_machine;

// X Y Z plus a position-controlled spindle S1 (kernel index 0) gaining
// 10 rpm per cycle up to 1000 rpm; speed reached within +-10 %.
config::Machine spindle_machine() {
  config::Machine m = xyz_machine(100, 100000);
  add_spindle_s1(m);
  return m;
}

// N1 M3 S1000 G1 X1 (waits for speed reached before it moves), N2 M30.
void load_program(KernelRig& rig) {
  nc::Block b = move(1, nc::Motion::linear, 1.0);
  nc::SpindleCommand c;
  c.name = "S";
  c.target = "S1";
  c.spindle_index = 0;
  c.din = true;
  c.m = nc::SpindleM::m3;
  c.rev_rpm = 1000;
  b.spindles.push_back(c);
  rig.push_block(0, b);
  rig.push_block(0, end_block(2));
}

struct Outcome {
  int speed_reached_events = 0;
  double speed_reached_rpm = 0;  // the actual speed the event reports
  bool done = false;
  double x_mm = 0;
};

// Ticks `cycles` times; before each cycle `measure` turns the last set
// point into the drive's measured actual speed (deg/s).
Outcome run(const std::function<double(double set_rpm)>& measure, int cycles) {
  KernelRig rig(spindle_machine());
  load_program(rig);
  TickInput in;
  TickOutput out;
  Outcome r;
  double pos_deg = 0;
  for (int i = 0; i < cycles && !rig.k.all_channels_done(); ++i) {
    const double speed_deg_s = measure(out.spindles[0].set_rpm);
    pos_deg += speed_deg_s * 0.001;
    in.spindle_measured[0] = spindle::DriveFeedback{speed_deg_s, pos_deg, true};
    rig.k.tick(in, out);
    for (const Event& e : out.events)
      if (e.kind() == EventKind::speed_reached) {
        ++r.speed_reached_events;
        r.speed_reached_rpm = e.get<spindle::SpeedReachedEvent>()->act_rpm;
      }
  }
  r.done = rig.k.all_channels_done();
  r.x_mm = rig.k.channel_state(0).axis_mcs[0];
  return r;
}

// The drive follows only to half the set speed: never "speed reached", the
// block never moves, however long the set point has stood at 1000 rpm.
TEST(SpindleMeasured, SpeedNeverReachedWhileTheDriveLagsBehind) {
  const Outcome r = run([](double set_rpm) { return spindle::rpm_to_deg_s(set_rpm / 2); }, 2000);
  EXPECT_EQ(r.speed_reached_events, 0);
  EXPECT_FALSE(r.done);
  EXPECT_EQ(r.x_mm, 0.0);
}

// The drive follows the set point one cycle late (a real drive's answer):
// speed reached with the measured speed, then the block moves and ends.
TEST(SpindleMeasured, SpeedReachedFromTheMeasuredSpeed) {
  const Outcome r = run([](double set_rpm) { return spindle::rpm_to_deg_s(set_rpm); }, 2000);
  EXPECT_EQ(r.speed_reached_events, 1);
  EXPECT_GE(r.speed_reached_rpm, 900);
  EXPECT_LE(r.speed_reached_rpm, 1100);
  EXPECT_TRUE(r.done);
  EXPECT_DOUBLE_EQ(r.x_mm, 1.0);
}

// A drive that runs at 1500 rpm whatever it is told is no more "reached"
// than one that lags: the band is around the commanded speed.
TEST(SpindleMeasured, SpeedAboveTheBandIsNotReached) {
  const Outcome r = run([](double) { return spindle::rpm_to_deg_s(1500); }, 2000);
  EXPECT_EQ(r.speed_reached_events, 0);
  EXPECT_FALSE(r.done);
}

// Without measured values (valid = false, nothing attached) the set point
// stands for the actual value: the spindle counts as reaching its speed
// with its own set point, as a sensorless one does.
TEST(SpindleMeasured, NoMeasuredValuesMeansTheSetPointCounts) {
  KernelRig rig(spindle_machine());
  load_program(rig);
  TickInput in;
  TickOutput out;
  int events = 0;
  for (int i = 0; i < 2000 && !rig.k.all_channels_done(); ++i) {
    rig.k.tick(in, out);
    for (const Event& e : out.events) events += e.kind() == EventKind::speed_reached;
    EXPECT_EQ(rig.k.spindle_status(0).act_rpm, rig.k.spindle_status(0).set_rpm);
  }
  EXPECT_EQ(events, 1);
  EXPECT_TRUE(rig.k.all_channels_done());
}

}  // namespace
}  // namespace nck::kernel
