// The CiA 402 power state machine (IEC 61800-7-201), both sides: the
// statusword patterns, the device's transitions 1-16, and the master that
// drives a device from power-up to "operation enabled", through a fault and
// its reset, a quick stop and a shutdown (issue 46, items 3 and 4).
#include <gtest/gtest.h>

#include "nck/drives/cia402.hpp"

namespace nck::drives::cia402 {
namespace {

TEST(Cia402, StatuswordPatternsDecode) {
  EXPECT_EQ(decode(0x0000), State::not_ready_to_switch_on);
  EXPECT_EQ(decode(0x0250), State::switch_on_disabled);  // remote, voltage bit ignored
  EXPECT_EQ(decode(0x0231), State::ready_to_switch_on);
  EXPECT_EQ(decode(0x0233), State::switched_on);
  EXPECT_EQ(decode(0x0637), State::operation_enabled);  // target reached too
  EXPECT_EQ(decode(0x0217), State::quick_stop_active);
  EXPECT_EQ(decode(0x021F), State::fault_reaction_active);
  EXPECT_EQ(decode(0x0208), State::fault);
  for (State s : {State::not_ready_to_switch_on, State::switch_on_disabled, State::ready_to_switch_on,
                  State::switched_on, State::operation_enabled, State::quick_stop_active,
                  State::fault_reaction_active, State::fault})
    EXPECT_EQ(decode(statusword_bits(s)), s) << name(s);
}

TEST(Cia402, DeviceFollowsTheProfilesTransitions) {
  Device d;
  d.step(cw::disable_voltage, false);  // 1: the drive's start-up
  EXPECT_EQ(d.state(), State::switch_on_disabled);
  d.step(cw::switch_on, false);  // not a transition from here
  EXPECT_EQ(d.state(), State::switch_on_disabled);
  d.step(cw::shutdown, false);  // 2
  EXPECT_EQ(d.state(), State::ready_to_switch_on);
  d.step(cw::switch_on, false);  // 3
  EXPECT_EQ(d.state(), State::switched_on);
  d.step(cw::enable_operation, false);  // 4
  EXPECT_EQ(d.state(), State::operation_enabled);
  d.step(cw::switch_on, false);  // 5: disable operation
  EXPECT_EQ(d.state(), State::switched_on);
  d.step(cw::enable_operation, false);
  d.step(cw::quick_stop, false);  // 11
  EXPECT_EQ(d.state(), State::quick_stop_active);
  d.step(cw::enable_operation, false);  // 16
  EXPECT_EQ(d.state(), State::operation_enabled);
  d.step(cw::shutdown, false);  // 8
  EXPECT_EQ(d.state(), State::ready_to_switch_on);
  d.step(cw::quick_stop, false);  // 7
  EXPECT_EQ(d.state(), State::switch_on_disabled);
}

TEST(Cia402, AFaultNeedsAResetEdge) {
  Device d(3);  // three cycles of fault reaction
  Master m;
  for (int i = 0; i < 10; ++i) d.step(m.controlword(d.state(), Goal::enabled), false);
  ASSERT_EQ(d.state(), State::operation_enabled);
  d.step(cw::enable_operation, true);  // 13
  EXPECT_EQ(d.state(), State::fault_reaction_active);
  d.step(cw::enable_operation, false);
  d.step(cw::enable_operation, false);
  EXPECT_EQ(d.state(), State::fault_reaction_active);
  d.step(cw::enable_operation, false);  // 14
  EXPECT_EQ(d.state(), State::fault);
  d.step(cw::fault_reset, false);  // bit 7 rises: the reset edge
  EXPECT_EQ(d.state(), State::switch_on_disabled);  // 15
  Device held(1);
  held.step(0, true);
  held.step(cw::fault_reset, false);
  ASSERT_EQ(held.state(), State::fault);
  held.step(cw::fault_reset, false);  // bit 7 still high: no edge, no reset
  EXPECT_EQ(held.state(), State::fault);
}

// The master brings a drive from power-up to "operation enabled" in the
// profile's four steps and reports how long it waited.
TEST(Cia402, MasterEnablesInFourCycles) {
  Device d;
  Master m;
  int cycles = 0;
  while (d.state() != State::operation_enabled && cycles < 20) {
    d.step(m.controlword(d.state(), Goal::enabled), false);
    ++cycles;
  }
  EXPECT_EQ(cycles, 4);  // start-up, shutdown, switch on, enable operation
  EXPECT_EQ(m.controlword(d.state(), Goal::enabled), cw::enable_operation);
  EXPECT_EQ(m.waiting_cycles(), 0u);
}

TEST(Cia402, MasterResetsAFaultOnlyToPowerUp) {
  Device d;
  Master m;
  d.step(0, true);
  d.step(0, false);
  ASSERT_EQ(d.state(), State::fault);
  for (int i = 0; i < 5; ++i) d.step(m.controlword(d.state(), Goal::disabled), false);
  EXPECT_EQ(d.state(), State::fault);  // disabled is reached: a fault is not reset for it
  int cycles = 0;
  while (d.state() != State::operation_enabled && cycles < 20) {
    d.step(m.controlword(d.state(), Goal::enabled), false);
    ++cycles;
  }
  EXPECT_EQ(d.state(), State::operation_enabled);
  EXPECT_LE(cycles, 5);  // reset edge, shutdown, switch on, enable (bit 7 was low)
}

TEST(Cia402, MasterQuickStopsAndShutsDown) {
  Device d;
  Master m;
  for (int i = 0; i < 5; ++i) d.step(m.controlword(d.state(), Goal::enabled), false);
  d.step(m.controlword(d.state(), Goal::quick_stop), false);
  EXPECT_EQ(d.state(), State::quick_stop_active);
  d.step(m.controlword(d.state(), Goal::disabled), false);
  EXPECT_EQ(d.state(), State::switch_on_disabled);
}

// A drive that never answers: the master keeps counting, so the caller's
// limit turns it into an error rather than a hang.
TEST(Cia402, MasterCountsTheCyclesADriveKeepsItWaiting) {
  Master m;
  for (int i = 0; i < 100; ++i) m.controlword(State::not_ready_to_switch_on, Goal::enabled);
  EXPECT_EQ(m.waiting_cycles(), 100u);
  m.controlword(State::not_ready_to_switch_on, Goal::disabled);
  EXPECT_EQ(m.waiting_cycles(), 1u);  // a new goal starts the count again
}

}  // namespace
}  // namespace nck::drives::cia402
