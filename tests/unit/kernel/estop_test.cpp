// E-stop and machine on as kernel inputs (TickInput::machine): the axes
// brake within their emergency deceleration along the path, the program
// ends in error, the drives are disabled at standstill, starts are refused
// with an ID, and only a reset after the release lets them run again.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "../seen_events.hpp"
#include "test_machine.hpp"

namespace nck::kernel {
namespace {

using testing::KernelRig;
using testing::move;
using testing::xyz_machine;

constexpr double kDt = 0.001;

using Recorder = test::EventLog;

config::Machine machine_with_emergency(double a_emergency) {
  return testing::xyz_machine_with_emergency(500, 2000, a_emergency);
}

// Runs a diagonal move at speed, E-stops it and checks every cycle's axis
// velocity and deceleration (each axis within a_bound); returns the cycles
// the path took to stand and the path speed it braked from.
std::pair<int, double> estop_while_moving(double a_bound, Recorder& rec, KernelRig& rig) {
  Kernel& k = rig.k;
  rig.push_block(0, move(1, nc::Motion::linear, 200.0, 200.0, {}, 24000));
  TickInput in;
  TickOutput out;
  for (int i = 0; i < 150; ++i) k.tick(in, out);
  const double v0 = out.channels[0].path_velocity_mm_s;
  EXPECT_GT(v0, 250.0);
  AxisArray last = out.channels[0].axis_mcs;
  std::array<double, 2> v_last{};
  for (int j = 0; j < 2; ++j) v_last[j] = v0 / std::sqrt(2.0);
  in.machine.estop = true;
  int cycles = 0;
  for (; cycles < 2000 && (out.channels[0].path_velocity_mm_s > 0 || cycles == 0); ++cycles) {
    k.tick(in, out);
    rec.take(out);
    for (int j = 0; j < 2; ++j) {
      const double v = (out.channels[0].axis_mcs[j] - last[j]) / kDt;
      EXPECT_LE(std::abs(v), 500.0 + 1e-9) << "axis " << j << " cycle " << cycles;
      EXPECT_LE(std::abs(v - v_last[j]) / kDt, a_bound * (1 + 1e-9) + 1e-6) << "axis " << j << " cycle " << cycles;
      v_last[j] = v;
    }
    last = out.channels[0].axis_mcs;
  }
  // A few cycles more: the program ends at standstill, nothing moves.
  for (int i = 0; i < 10; ++i) {
    k.tick(in, out);
    rec.take(out);
    EXPECT_EQ(out.channels[0].axis_mcs[0], last[0]);
  }
  return {cycles, v0};
}

TEST(Estop, BrakesWithinTheEmergencyDecelerationThenDisablesTheDrives) {
  KernelRig rig(machine_with_emergency(3000));
  Recorder rec;
  const auto [cycles, v0] = estop_while_moving(3000, rec, rig);
  // The path brakes with 3000 mm/s^2 (each axis of the diagonal with
  // 2121), harder than a feedhold's 2828 along the diagonal would.
  EXPECT_LE(cycles, static_cast<int>(v0 / 3000 / kDt) + 2);
  EXPECT_GE(cycles, static_cast<int>(v0 / 3000 / kDt) - 1);
  EXPECT_EQ(rec.count(ErrorId::KernelEmergencyStop), 1);
  EXPECT_EQ(rig.k.program_state(0), ProgramState::error);
  EXPECT_TRUE(rig.k.all_channels_done());
  const MachineOutput& m = rig.k.machine_state();
  EXPECT_TRUE(m.estop);
  EXPECT_TRUE(m.reset_needed);
  EXPECT_FALSE(m.drives_enabled);
  // The `machine` events: E-stop with the drives still on, then off at standstill.
  const auto machine = test::seen<ev::Machine>(rec.events);
  ASSERT_EQ(machine.size(), 2u);
  EXPECT_TRUE(machine[0].estop && machine[0].drives_enabled);
  EXPECT_FALSE(machine[1].drives_enabled);
  EXPECT_EQ(machine[0].channel, 0);
}

TEST(Estop, ZeroEmergencyDecelerationMeansAMax) {
  KernelRig rig(machine_with_emergency(0));
  Recorder rec;
  const auto [cycles, v0] = estop_while_moving(2000, rec, rig);
  // a_max (2000 per axis): the path's own deceleration along the diagonal, 2828.
  EXPECT_GE(cycles, static_cast<int>(v0 / (2000 * std::sqrt(2.0)) / kDt) - 1);
}

TEST(Estop, RefusesCycleStartMdiAndJogUntilAResetAfterItsRelease) {
  KernelRig rig(machine_with_emergency(3000));
  Kernel& k = rig.k;
  TickInput in;
  TickOutput out;
  Recorder rec;
  in.machine.estop = true;
  k.tick(in, out);
  rec.take(out);
  EXPECT_EQ(rec.count(ErrorId::KernelEmergencyStop), 1);
  EXPECT_EQ(k.program_state(0), ProgramState::error);
  // Cycle start, a jog: refused with the E-stop's ID, nothing moves.
  in.channels[0].cycle_start = true;
  JogRequest jog;
  jog.kind = JogRequest::Kind::continuous;
  jog.axis = 0;
  (void)in.channels[0].jogs.push_back(jog);
  k.tick(in, out);
  rec.take(out);
  in.channels[0].jogs.clear();
  EXPECT_EQ(rec.count(ErrorId::KernelEstopRefused), 2);
  for (int i = 0; i < 50; ++i) k.tick(in, out);
  EXPECT_EQ(out.channels[0].axis_mcs[0], 0.0);
  // A reset while the E-stop is on changes nothing.
  in.channels[0].cycle_start = false;
  in.channels[0].reset = true;
  k.tick(in, out);
  in.channels[0].reset = false;
  EXPECT_EQ(k.program_state(0), ProgramState::error);
  // Released: still refused until the reset.
  in.machine.estop = false;
  in.channels[0].cycle_start = true;
  rec.events.clear();
  k.tick(in, out);
  rec.take(out);
  EXPECT_EQ(rec.count(ErrorId::KernelEstopRefused), 1);
  EXPECT_TRUE(k.machine_state().reset_needed);
  EXPECT_TRUE(k.machine_state().drives_enabled);  // enabled again: nothing is to be braked
  in.channels[0].cycle_start = false;
  in.channels[0].reset = true;
  k.tick(in, out);
  in.channels[0].reset = false;
  EXPECT_EQ(k.program_state(0), ProgramState::idle);
  EXPECT_FALSE(k.machine_state().reset_needed);
  rec.events.clear();
  in.channels[0].cycle_start = true;
  k.tick(in, out);
  rec.take(out);
  EXPECT_EQ(rec.count(ErrorId::KernelEstopRefused), 0);
}

TEST(Estop, ABlockQueuedDuringTheEstopDoesNotStart) {
  KernelRig rig(machine_with_emergency(3000));
  Kernel& k = rig.k;
  TickInput in;
  TickOutput out;
  in.machine.estop = true;
  k.tick(in, out);
  rig.push_block(0, move(1, nc::Motion::linear, 10.0));
  for (int i = 0; i < 100; ++i) k.tick(in, out);
  EXPECT_EQ(out.channels[0].axis_mcs[0], 0.0);
}

TEST(MachineOn, OffBrakesTheProgramAsAResetAndRefusesStarts) {
  KernelRig rig(xyz_machine(500, 2000));
  Kernel& k = rig.k;
  rig.push_block(0, move(1, nc::Motion::linear, 200.0, {}, {}, 12000));
  TickInput in;
  TickOutput out;
  Recorder rec;
  for (int i = 0; i < 100; ++i) k.tick(in, out);
  const double v0 = out.channels[0].path_velocity_mm_s;
  EXPECT_GT(v0, 150.0);
  in.machine.machine_on = false;
  double last = out.channels[0].axis_mcs[0], v_last = v0;
  for (int i = 0; i < 500; ++i) {
    k.tick(in, out);
    rec.take(out);
    const double v = (out.channels[0].axis_mcs[0] - last) / kDt;
    EXPECT_LE(std::abs(v - v_last) / kDt, 2000 * (1 + 1e-9));
    last = out.channels[0].axis_mcs[0];
    v_last = v;
  }
  EXPECT_EQ(rec.count(ErrorId::KernelMachineOff), 1);
  EXPECT_EQ(k.program_state(0), ProgramState::idle);  // a reset, not an error
  EXPECT_FALSE(k.machine_state().drives_enabled);
  EXPECT_FALSE(k.machine_state().reset_needed);
  in.channels[0].cycle_start = true;
  rec.events.clear();
  k.tick(in, out);
  rec.take(out);
  EXPECT_EQ(rec.count(ErrorId::KernelMachineOffRefused), 1);
  in.machine.machine_on = true;
  rec.events.clear();
  k.tick(in, out);
  rec.take(out);
  EXPECT_EQ(rec.count(ErrorId::KernelMachineOffRefused), 0);
  EXPECT_TRUE(k.machine_state().drives_enabled);
}

TEST(MachineOn, AProgramNotYetStartedWaitsForMachineOn) {
  KernelRig rig(xyz_machine(500, 2000));
  Kernel& k = rig.k;
  TickInput in;
  TickOutput out;
  in.machine.machine_on = false;
  rig.push_block(0, move(1, nc::Motion::linear, 10.0));
  rig.push_block(0, testing::end_block(2));
  for (int i = 0; i < 100; ++i) k.tick(in, out);
  EXPECT_EQ(out.channels[0].axis_mcs[0], 0.0);
  EXPECT_FALSE(k.all_channels_done());
  in.machine.machine_on = true;
  for (int i = 0; i < 5000 && !k.all_channels_done(); ++i) k.tick(in, out);
  EXPECT_TRUE(k.all_channels_done());
  EXPECT_DOUBLE_EQ(out.channels[0].axis_mcs[0], 10.0);
}

TEST(Estop, DefaultInputsEmitNoMachineEvent) {
  KernelRig rig(xyz_machine());
  rig.push_block(0, move(1, nc::Motion::linear, 10.0));
  rig.push_block(0, testing::end_block(2));
  TickInput in;
  TickOutput out;
  Recorder rec;
  for (int i = 0; i < 5000 && !rig.k.all_channels_done(); ++i) {
    rig.k.tick(in, out);
    rec.take(out);
  }
  EXPECT_TRUE(test::seen<ev::Machine>(rec.events).empty());
  EXPECT_TRUE(out.machine.drives_enabled);
}

}  // namespace
}  // namespace nck::kernel
