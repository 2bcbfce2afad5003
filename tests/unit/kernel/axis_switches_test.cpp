// Amplifier faults and limit switches as kernel inputs (TickInput::axes):
// an amplifier fault or a limit switch that comes on brakes every axis of
// the channel within its velocity and emergency deceleration and names the
// axis; an amplifier fault refuses starts until it is gone and a reset was
// given; after a limit switch, jogs away from it move and jogs further into
// it are refused.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../seen_events.hpp"
#include "test_machine.hpp"

namespace nck::kernel {
namespace {

using testing::KernelRig;
using testing::move;

constexpr double kDt = 0.001;
constexpr double kVmax = 500, kAmax = 2000, kAemergency = 3000;

struct Recorder : test::EventLog {
  // The axis the first diagnosis with this ID names (-2: none seen, -1: no axis).
  int axis_of(ErrorId id) const {
    for (const Event& e : events) {
      if (test::diagnosis_id(e) != id) continue;
      if (const auto* d = e.get<ev::Error>()) return d->axis ? *d->axis : -1;
      if (const auto* w = e.get<ev::Warning>()) return w->axis ? *w->axis : -1;
    }
    return -2;
  }
};

config::Machine machine() { return testing::xyz_machine_with_emergency(kVmax, kAmax, kAemergency); }

JogRequest jog(std::int8_t axis, std::int8_t direction) {
  JogRequest r;
  r.kind = JogRequest::Kind::continuous;
  r.axis = axis;
  r.direction = direction;
  return r;
}

// Runs a diagonal move in X and Y at speed, then sets one input and checks
// every cycle until standstill: each axis within its velocity and the
// emergency deceleration. Returns the cycles the path took to stand.
int brake_on_input(bool AxisSwitches::*input, std::size_t axis, Recorder& rec, KernelRig& rig) {
  Kernel& k = rig.k;
  rig.push_block(0, move(1, nc::Motion::linear, 200.0, 200.0, {}, 24000));
  TickInput in;
  TickOutput out;
  for (int i = 0; i < 150; ++i) k.tick(in, out);
  const double v0 = out.channels[0].path_velocity_mm_s;
  EXPECT_GT(v0, 250.0);
  AxisArray last = out.channels[0].axis_mcs;
  std::array<double, 2> v_last{v0 / std::sqrt(2.0), v0 / std::sqrt(2.0)};
  in.axes[axis].*input = true;
  int cycles = 0;
  for (; cycles < 2000 && (out.channels[0].path_velocity_mm_s > 0 || cycles == 0); ++cycles) {
    k.tick(in, out);
    rec.take(out);
    for (int j = 0; j < 2; ++j) {
      const double v = (out.channels[0].axis_mcs[j] - last[j]) / kDt;
      EXPECT_LE(std::abs(v), kVmax + 1e-9) << "axis " << j << " cycle " << cycles;
      EXPECT_LE(std::abs(v - v_last[j]) / kDt, kAemergency * (1 + 1e-9) + 1e-6) << "axis " << j << " cycle " << cycles;
      v_last[j] = v;
    }
    last = out.channels[0].axis_mcs;
  }
  for (int i = 0; i < 10; ++i) {  // the program has ended at standstill
    k.tick(in, out);
    rec.take(out);
    EXPECT_EQ(out.channels[0].axis_mcs[0], last[0]);
  }
  EXPECT_LE(cycles, static_cast<int>(v0 / kAemergency / kDt) + 2);  // the emergency deceleration, not a_max
  return cycles;
}

TEST(AmpFault, InMotionNamesTheAxisBrakesWithinLimitsAndDisablesTheDrives) {
  KernelRig rig(machine());
  Recorder rec;
  brake_on_input(&AxisSwitches::amp_fault, 1, rec, rig);
  EXPECT_EQ(rec.count(ErrorId::KernelAmpFault), 1);  // once, though the input stays on
  EXPECT_EQ(rec.axis_of(ErrorId::KernelAmpFault), 1);
  EXPECT_EQ(rig.k.program_state(0), ProgramState::error);
  EXPECT_TRUE(rig.k.all_channels_done());
  EXPECT_FALSE(rig.k.machine_state().drives_enabled);
  EXPECT_TRUE(rig.k.machine_state().reset_needed);
}

TEST(AmpFault, RefusesStartsUntilTheFaultIsGoneAndAResetWasGiven) {
  KernelRig rig(machine());
  Kernel& k = rig.k;
  TickInput in;
  TickOutput out;
  Recorder rec;
  in.axes[0].amp_fault = true;
  k.tick(in, out);
  rec.take(out);
  EXPECT_EQ(rec.count(ErrorId::KernelAmpFault), 1);
  // Cycle start and a jog: refused with the fault's refusal, nothing moves.
  in.channels[0].cycle_start = true;
  (void)in.channels[0].jogs.push_back(jog(0, 1));
  k.tick(in, out);
  rec.take(out);
  in.channels[0].jogs.clear();
  in.channels[0].cycle_start = false;
  EXPECT_EQ(rec.count(ErrorId::KernelAmpFaultRefused), 2);
  // A reset while the fault is on changes nothing.
  in.channels[0].reset = true;
  k.tick(in, out);
  in.channels[0].reset = false;
  EXPECT_EQ(k.program_state(0), ProgramState::error);
  EXPECT_FALSE(k.machine_state().drives_enabled);
  // The fault goes: starts are still refused until the reset.
  in.axes[0].amp_fault = false;
  in.channels[0].cycle_start = true;
  rec.events.clear();
  k.tick(in, out);
  rec.take(out);
  in.channels[0].cycle_start = false;
  EXPECT_EQ(rec.count(ErrorId::KernelAmpFaultRefused), 1);
  EXPECT_FALSE(k.machine_state().drives_enabled);
  in.channels[0].reset = true;
  k.tick(in, out);
  in.channels[0].reset = false;
  EXPECT_EQ(k.program_state(0), ProgramState::idle);
  EXPECT_TRUE(k.machine_state().drives_enabled);
  EXPECT_FALSE(k.machine_state().reset_needed);
  rec.events.clear();
  (void)in.channels[0].jogs.push_back(jog(0, 1));
  k.tick(in, out);
  rec.take(out);
  in.channels[0].jogs.clear();
  EXPECT_EQ(rec.count(ErrorId::KernelAmpFaultRefused), 0);
  for (int i = 0; i < 50; ++i) k.tick(in, out);
  EXPECT_GT(out.channels[0].axis_mcs[0], 0.0);  // the jog moves again
}

TEST(AmpFault, OnADisabledDriveRaisesNothing) {
  KernelRig rig(machine());
  Kernel& k = rig.k;
  TickInput in;
  TickOutput out;
  Recorder rec;
  in.machine.machine_on = false;  // drives disabled at standstill
  k.tick(in, out);
  in.axes[2].amp_fault = true;
  for (int i = 0; i < 5; ++i) {
    k.tick(in, out);
    rec.take(out);
  }
  EXPECT_EQ(rec.count(ErrorId::KernelAmpFault), 0);
  in.machine.machine_on = true;  // enabled again: the fault counts
  for (int i = 0; i < 3; ++i) {
    k.tick(in, out);
    rec.take(out);
  }
  EXPECT_EQ(rec.count(ErrorId::KernelAmpFault), 1);
  EXPECT_EQ(rec.axis_of(ErrorId::KernelAmpFault), 2);
}

TEST(LimitSwitch, ReachedInMotionNamesAxisAndDirectionAndBrakes) {
  KernelRig rig(machine());
  Recorder rec;
  brake_on_input(&AxisSwitches::pos_limit, 0, rec, rig);
  EXPECT_EQ(rec.count(ErrorId::KernelLimitSwitchPos), 1);
  EXPECT_EQ(rec.count(ErrorId::KernelLimitSwitchNeg), 0);
  EXPECT_EQ(rec.axis_of(ErrorId::KernelLimitSwitchPos), 0);
  EXPECT_EQ(rig.k.program_state(0), ProgramState::error);
  EXPECT_TRUE(rig.k.machine_state().drives_enabled);  // a limit switch does not switch the drives off
}

TEST(LimitSwitch, AfterAResetJogsAwayMoveAndJogsFurtherInAreRefused) {
  KernelRig rig(machine());
  Kernel& k = rig.k;
  TickInput in;
  TickOutput out;
  Recorder rec;
  in.axes[1].neg_limit = true;
  k.tick(in, out);
  rec.take(out);
  EXPECT_EQ(rec.count(ErrorId::KernelLimitSwitchNeg), 1);
  EXPECT_EQ(rec.axis_of(ErrorId::KernelLimitSwitchNeg), 1);
  EXPECT_EQ(k.program_state(0), ProgramState::error);
  in.channels[0].reset = true;
  k.tick(in, out);
  in.channels[0].reset = false;
  EXPECT_EQ(k.program_state(0), ProgramState::idle);  // the switch stays on: the reset clears the error
  // Further in (Y-): refused, nothing moves.
  rec.events.clear();
  (void)in.channels[0].jogs.push_back(jog(1, -1));
  k.tick(in, out);
  rec.take(out);
  in.channels[0].jogs.clear();
  EXPECT_EQ(rec.count(ErrorId::KernelJogIntoLimitSwitch), 1);
  EXPECT_EQ(rec.axis_of(ErrorId::KernelJogIntoLimitSwitch), 1);
  for (int i = 0; i < 20; ++i) k.tick(in, out);
  EXPECT_EQ(out.channels[0].axis_mcs[1], 0.0);
  // Away (Y+), and another axis: they move.
  (void)in.channels[0].jogs.push_back(jog(1, 1));
  (void)in.channels[0].jogs.push_back(jog(0, -1));
  k.tick(in, out);
  rec.take(out);
  in.channels[0].jogs.clear();
  for (int i = 0; i < 50; ++i) {
    k.tick(in, out);
    rec.take(out);
  }
  EXPECT_GT(out.channels[0].axis_mcs[1], 0.0);
  EXPECT_LT(out.channels[0].axis_mcs[0], 0.0);
  EXPECT_EQ(rec.count(ErrorId::KernelJogIntoLimitSwitch), 1);
  EXPECT_EQ(rec.count(ErrorId::KernelLimitSwitchNeg), 0);  // moving off the switch raises nothing
  EXPECT_EQ(k.program_state(0), ProgramState::idle);
}

}  // namespace
}  // namespace nck::kernel
