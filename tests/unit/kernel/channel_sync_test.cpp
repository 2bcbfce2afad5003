// The channel's synchronisation of PLC and spindle functions with its motion
// (src/kernel/units/sync_unit.cpp, FCT-S1 2.5), driven through the kernel's only
// PLC interface: outputs leave in TickOutput::tech_outputs, acknowledgements
// come back in TickInput::acks. The test plays the PLC and decides in which
// cycle each output is acknowledged.
//
// Time base of every test: cycle_time_us = 1000, so cycle i starts at
// t = i ms. The machine is xyz_machine(100, 100000): a path speed of
// 100 mm/s (F6000, and the rapid speed rapid_mm_s = max_speed_mm_s = 100 mm/s) is
// reached in the first cycle (100000 mm/s^2 * 1 ms = 100 mm/s) and the
// discrete braking staircase never cuts it below 100 mm/s before the last
// cycle, so a 1 mm move is exactly 10 cycles of 0.1 mm.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <utility>
#include <vector>

#include "nck/kernel/kernel.hpp"
#include "test_machine.hpp"
#include "../seen_events.hpp"

namespace nck::kernel {
namespace {

using testing::end_block;
using testing::KernelRig;
using testing::move;
using testing::xyz_machine;
namespace sync = config::sync;

constexpr double kStep_mm = 0.1;  // path per cycle at 100 mm/s
constexpr int kOneMm = 10;        // cycles of a 1 mm move

config::Machine fast_machine() { return xyz_machine(100, 100000); }

int cycle_of(double t_s) { return static_cast<int>(std::lround(t_s * 1000.0)); }

struct Issued {
  plc::OutputHandle handle = plc::kNoHandle;
  plc::TechOutput output;
  int cycle = 0;  // the cycle whose TickOutput carried it
};

// What a run produced, cycle by cycle.
struct Log {
  std::vector<Event> events;
  std::vector<Issued> issued;
  std::vector<double> x;  // channel 1, axis X, after each cycle
  std::vector<ChannelStatus> status;
  std::vector<bool> speed_reached;  // spindle 0 after each cycle (when there is one)

  template <class T>
  std::vector<test::Seen<T>> of() const {
    return test::seen<T>(events);
  }
  // First cycle in which X has left 0 (-1: never).
  int motion_start() const {
    for (std::size_t i = 0; i < x.size(); ++i)
      if (x[i] > 0) return static_cast<int>(i);
    return -1;
  }
  int cycles() const { return static_cast<int>(x.size()); }
};

// The PLC's answer to an output: the cycle whose TickInput carries the
// acknowledgement, or -1 for never.
using AckPolicy = std::function<int(const Issued&)>;
AckPolicy never() {
  return [](const Issued&) { return -1; };
}
AckPolicy at(int cycle) {
  return [cycle](const Issued&) { return cycle; };
}
AckPolicy after(int cycles) {
  return [cycles](const Issued& o) { return o.cycle + cycles; };
}

// Runs until every channel is done or max_cycles have passed.
Log run(Kernel& k, const AckPolicy& plc, int max_cycles = 2000, TickInput in = {}) {
  Log log;
  std::vector<std::pair<int, plc::PlcAck>> pending;
  TickOutput out;
  for (int i = 0; i < max_cycles && !k.all_channels_done(); ++i) {
    in.acks.clear();
    for (auto it = pending.begin(); it != pending.end();) {
      EXPECT_GT(it->first, i - 1) << "an acknowledgement before its output";
      if (it->first == i) {
        (void)in.acks.push_back(it->second);
        it = pending.erase(it);
      } else {
        ++it;
      }
    }
    k.tick(in, out);
    EXPECT_EQ(cycle_of(out.t_s), i);
    for (const Event& e : out.events) log.events.push_back(e);
    log.x.push_back(out.channels[0].axis_mcs[0]);
    log.status.push_back(out.channels[0].status);
    log.speed_reached.push_back(k.spindle_count() > 0 && k.spindle_status(0).speed_reached);
    for (const TechRequest& t : out.tech_outputs) {
      const Issued o{t.handle, t.output, i};
      log.issued.push_back(o);
      const int when = plc(o);
      if (when >= 0) pending.push_back({when, plc::PlcAck{t.handle, t.output, when * 1e-3}});
    }
  }
  return log;
}

nc::Block with_m(nc::Block b, std::initializer_list<int> ms) {
  for (int m : ms) b.m.push_back(m);
  return b;
}

nc::Block nop(std::uint32_t line) {
  nc::Block b;
  b.line = line;
  return b;
}

// Channel M function M<m> with the given synchronisation in a G1 X1 block,
// then M30.
Log m_function_run(int m, std::uint32_t bits, const AckPolicy& plc) {
  config::Machine machine = fast_machine();
  machine.channels[0].m_synch[static_cast<std::size_t>(m)] = bits;
  KernelRig rig(machine);
  rig.push_block(0, with_m(move(1, nc::Motion::linear, 1.0), {m}));
  rig.push_block(0, end_block(2));
  return run(rig.k, plc);
}

void expect_output(const Issued& o, int cycle, int number, std::uint32_t bits) {
  EXPECT_EQ(o.cycle, cycle);
  EXPECT_EQ(o.output.kind, plc::TechKind::m);
  EXPECT_EQ(o.output.number, number);
  EXPECT_EQ(o.output.channel, 1);
  EXPECT_EQ(o.output.sync, bits);
  EXPECT_NE(o.handle, plc::kNoHandle);
}

// --- channel M functions --------------------------------------------------

// MVS_SVS: output in cycle 0, before the motion; the PLC acknowledges in
// cycle 5, so the wait announced in cycle 0 ends in cycle 5 and the first
// 0.1 mm is travelled in that same cycle (the acknowledgement is read before
// the channel runs). 10 cycles of motion: cycles 5..14; the block ends and
// M30 follows in cycle 15.
TEST(ChannelSync, MvsSvsMotionStartsOnlyWithTheAcknowledgement) {
  const Log r = m_function_run(10, sync::MVS_SVS, at(5));
  ASSERT_EQ(r.issued.size(), 1u);
  expect_output(r.issued[0], 0, 10, sync::MVS_SVS);
  const auto waits = r.of<kernel::ev::Wait>();
  const auto ends = r.of<kernel::ev::WaitEnd>();
  ASSERT_EQ(waits.size(), 1u);
  ASSERT_EQ(ends.size(), 1u);
  EXPECT_EQ(cycle_of(waits[0].t_s), 0);
  EXPECT_EQ(waits[0].fn, plc::TechKind::m);
  EXPECT_EQ(waits[0].number, 10);
  EXPECT_EQ(waits[0].reason, WaitReason::plc_ack);
  EXPECT_EQ(waits[0].at.line, 1u);
  EXPECT_EQ(cycle_of(ends[0].t_s), 5);
  EXPECT_EQ(cycle_of(r.of<kernel::ev::PlcAck>().at(0).t_s), 5);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(r.x[i], 0.0) << "cycle " << i;
    EXPECT_EQ(r.status[i], ChannelStatus::waiting) << "cycle " << i;
  }
  EXPECT_EQ(r.motion_start(), 5);
  EXPECT_NEAR(r.x[5], kStep_mm, 1e-12);
  EXPECT_EQ(r.status[5], ChannelStatus::running);
  EXPECT_DOUBLE_EQ(r.x[5 + kOneMm - 1], 1.0);
  EXPECT_EQ(cycle_of(r.of<kernel::ev::End>().at(0).t_s), 5 + kOneMm);
}

// Without an acknowledgement the MVS_SVS block never moves.
TEST(ChannelSync, MvsSvsWithoutAcknowledgementNeverMoves) {
  const Log r = m_function_run(10, sync::MVS_SVS, never());
  EXPECT_EQ(r.cycles(), 2000);
  EXPECT_EQ(r.motion_start(), -1);
  EXPECT_EQ(r.status.back(), ChannelStatus::waiting);
  EXPECT_EQ(r.of<kernel::ev::Wait>().size(), 1u);  // announced once, not every cycle
  EXPECT_TRUE(r.of<kernel::ev::WaitEnd>().empty());
}

// MVS_SNS: output in cycle 0 and the motion runs at once (cycles 0..9).
// The wait is checked in the cycle after the motion, 10: not acknowledged,
// so a wait starts there; the acknowledgement in cycle 20 ends it, the block
// and (M30 following) the program in cycle 20.
TEST(ChannelSync, MvsSnsMovesThenWaitsForTheAcknowledgement) {
  const Log r = m_function_run(11, sync::MVS_SNS, at(20));
  ASSERT_EQ(r.issued.size(), 1u);
  expect_output(r.issued[0], 0, 11, sync::MVS_SNS);
  EXPECT_EQ(r.motion_start(), 0);
  EXPECT_DOUBLE_EQ(r.x[kOneMm - 1], 1.0);
  const auto waits = r.of<kernel::ev::Wait>();
  const auto ends = r.of<kernel::ev::WaitEnd>();
  ASSERT_EQ(waits.size(), 1u);
  ASSERT_EQ(ends.size(), 1u);
  EXPECT_EQ(cycle_of(waits[0].t_s), kOneMm);
  EXPECT_EQ(cycle_of(ends[0].t_s), 20);
  for (int i = kOneMm; i < 20; ++i) EXPECT_EQ(r.status[i], ChannelStatus::waiting) << "cycle " << i;
  EXPECT_EQ(cycle_of(r.of<kernel::ev::End>().at(0).t_s), 20);
}

// MVS_SNS acknowledged during the motion (cycle 3): nothing is left to wait
// for after it, so the block ends in cycle 10 as a plain move would.
TEST(ChannelSync, MvsSnsAcknowledgedDuringTheMotionDoesNotWait) {
  const Log r = m_function_run(11, sync::MVS_SNS, at(3));
  EXPECT_EQ(r.motion_start(), 0);
  EXPECT_TRUE(r.of<kernel::ev::Wait>().empty());
  EXPECT_EQ(cycle_of(r.of<kernel::ev::End>().at(0).t_s), kOneMm);
}

// MNS_SNS: nothing before the motion (cycles 0..9); the output leaves in the
// motion's last cycle 9, with X already at 1. The PLC answers two cycles
// after it saw the output (cycle 11); the wait starts in cycle 10 and ends,
// with the block and the program, in cycle 11.
TEST(ChannelSync, MnsSnsOutputsAfterTheMotionThenWaits) {
  const Log r = m_function_run(12, sync::MNS_SNS, after(2));
  ASSERT_EQ(r.issued.size(), 1u);
  expect_output(r.issued[0], kOneMm - 1, 12, sync::MNS_SNS);
  EXPECT_DOUBLE_EQ(r.x[kOneMm - 1], 1.0);
  EXPECT_LT(r.x[kOneMm - 2], 1.0);
  EXPECT_EQ(r.motion_start(), 0);
  const auto outs = r.of<kernel::ev::PlcOut>();
  ASSERT_EQ(outs.size(), 1u);
  EXPECT_EQ(cycle_of(outs[0].t_s), kOneMm - 1);
  const auto waits = r.of<kernel::ev::Wait>();
  const auto ends = r.of<kernel::ev::WaitEnd>();
  ASSERT_EQ(waits.size(), 1u);
  ASSERT_EQ(ends.size(), 1u);
  EXPECT_EQ(cycle_of(waits[0].t_s), kOneMm);
  EXPECT_EQ(cycle_of(ends[0].t_s), kOneMm + 1);
  EXPECT_EQ(cycle_of(r.of<kernel::ev::End>().at(0).t_s), kOneMm + 1);
}

// MOS: output in cycle 0, never acknowledged, never waited for: the block
// takes its 10 motion cycles and M30 runs in cycle 10. An M number left at
// NO_SYNCH (m_synch's default 0) in the same block is not output at all.
TEST(ChannelSync, MosOutputsWithoutWaitingAndNoSynchIsNotOutput) {
  config::Machine machine = fast_machine();
  machine.channels[0].m_synch[13] = sync::MOS;
  KernelRig rig(machine);
  rig.push_block(0, with_m(move(1, nc::Motion::linear, 1.0), {13, 14}));
  rig.push_block(0, end_block(2));
  const Log r = run(rig.k, never());
  ASSERT_EQ(r.issued.size(), 1u);
  expect_output(r.issued[0], 0, 13, sync::MOS);
  EXPECT_EQ(r.motion_start(), 0);
  EXPECT_TRUE(r.of<kernel::ev::Wait>().empty());
  EXPECT_EQ(cycle_of(r.of<kernel::ev::End>().at(0).t_s), kOneMm);
}

// MVS_SLM: M15 alone (N1) goes out in cycle 0 and nothing waits there; the
// rapid move N2 (G0 X1) runs in cycles 0..9 without waiting; the feed move
// N3 (G1 X2) starts in cycle 10 and waits there, before its motion, until
// the acknowledgement in cycle 30; it moves in cycles 30..39 and M30 runs in
// cycle 40.
TEST(ChannelSync, MvsSlmWaitsAtTheNextFeedMoveNotAtARapidMove) {
  config::Machine machine = fast_machine();
  machine.channels[0].m_synch[15] = sync::MVS_SLM;
  KernelRig rig(machine);
  rig.push_block(0, with_m(nop(1), {15}));
  rig.push_block(0, move(2, nc::Motion::rapid, 1.0));
  rig.push_block(0, move(3, nc::Motion::linear, 2.0));
  rig.push_block(0, end_block(4));
  const Log r = run(rig.k, at(30));
  ASSERT_EQ(r.issued.size(), 1u);
  expect_output(r.issued[0], 0, 15, sync::MVS_SLM);
  EXPECT_EQ(r.motion_start(), 0);  // the rapid move does not wait
  EXPECT_DOUBLE_EQ(r.x[kOneMm - 1], 1.0);
  const auto waits = r.of<kernel::ev::Wait>();
  const auto ends = r.of<kernel::ev::WaitEnd>();
  ASSERT_EQ(waits.size(), 1u);
  ASSERT_EQ(ends.size(), 1u);
  EXPECT_EQ(cycle_of(waits[0].t_s), kOneMm);
  EXPECT_EQ(waits[0].at.line, 3u);
  EXPECT_EQ(waits[0].number, 15);
  EXPECT_EQ(cycle_of(ends[0].t_s), 30);
  for (int i = kOneMm; i < 30; ++i) EXPECT_DOUBLE_EQ(r.x[i], 1.0) << "cycle " << i;
  EXPECT_NEAR(r.x[30], 1.0 + kStep_mm, 1e-12);
  EXPECT_EQ(cycle_of(r.of<kernel::ev::End>().at(0).t_s), 30 + kOneMm);
}

// MVS_SLM acknowledged during the rapid move (cycle 4): the feed move N3
// finds it acknowledged and goes straight on: 0..9 rapid, 10..19 feed, M30
// in cycle 20, no wait event.
TEST(ChannelSync, MvsSlmAcknowledgedBeforeTheFeedMoveDoesNotWait) {
  config::Machine machine = fast_machine();
  machine.channels[0].m_synch[15] = sync::MVS_SLM;
  KernelRig rig(machine);
  rig.push_block(0, with_m(nop(1), {15}));
  rig.push_block(0, move(2, nc::Motion::rapid, 1.0));
  rig.push_block(0, move(3, nc::Motion::linear, 2.0));
  rig.push_block(0, end_block(4));
  const Log r = run(rig.k, at(4));
  EXPECT_TRUE(r.of<kernel::ev::Wait>().empty());
  EXPECT_NEAR(r.x[kOneMm], 1.0 + kStep_mm, 1e-12);
  EXPECT_EQ(cycle_of(r.of<kernel::ev::End>().at(0).t_s), 2 * kOneMm);
}

// MVS_SLP: M16 (N1) is output in cycle 0; the feed move N2 (cycles 0..9) does
// not synchronise it; #EXPL SYN (N3) does, from cycle 10 until the
// acknowledgement in cycle 25, when M30 follows.
TEST(ChannelSync, MvsSlpWaitsAtExplicitSynchronisationOnly) {
  config::Machine machine = fast_machine();
  machine.channels[0].m_synch[16] = sync::MVS_SLP;
  KernelRig rig(machine);
  rig.push_block(0, with_m(nop(1), {16}));
  rig.push_block(0, move(2, nc::Motion::linear, 1.0));
  nc::Block syn = nop(3);
  syn.hash = nc::ExplSyn{};
  rig.push_block(0, syn);
  rig.push_block(0, end_block(4));
  const Log r = run(rig.k, at(25));
  EXPECT_EQ(r.motion_start(), 0);
  const auto waits = r.of<kernel::ev::Wait>();
  const auto ends = r.of<kernel::ev::WaitEnd>();
  ASSERT_EQ(waits.size(), 1u);
  ASSERT_EQ(ends.size(), 1u);
  EXPECT_EQ(cycle_of(waits[0].t_s), kOneMm);
  EXPECT_EQ(waits[0].at.line, 3u);
  EXPECT_EQ(cycle_of(ends[0].t_s), 25);
  EXPECT_EQ(cycle_of(r.of<kernel::ev::End>().at(0).t_s), 25);
}

// --- spindle functions ----------------------------------------------------

// X Y Z plus one spindle S1 (log 6, the main spindle "S", kernel index 0),
// built so its speed can be followed by hand: no drive attached and no
// measured values (the actual speed is the set speed), 60000 deg/s^2 = 10 rpm more per
// cycle, at most 6000 deg/s = 1000 rpm, "speed reached" within 9.5 % of the
// commanded speed (vb_prozent 95 permille).
config::Machine spindle_machine() {
  config::Machine m = fast_machine();
  config::AxisConfig& ax = testing::add_spindle_s1(m);
  ax.drive_mode = config::DriveMode::open_loop;
  ax.speed_reached_tolerance_permille = 95;
  return m;
}

// A feed move to x with M3 S<rpm> of the main spindle in the same block.
nc::Block move_with_m3(std::uint32_t line, double x, double rpm) {
  nc::Block b = move(line, nc::Motion::linear, x);
  nc::SpindleCommand c;
  c.name = "S";
  c.target = "S1";
  c.spindle_index = 0;  // resolved by the decoder in a real run
  c.din = true;
  c.m = nc::SpindleM::m3;
  c.rev_rpm = rpm;
  b.spindles.push_back(c);
  return b;
}

// A spindle started in cycle s gains 10 rpm in each cycle from s on (the
// spindle runs after the channel in the same cycle): 10 * (i - s + 1) rpm
// after cycle i. Speed reached for M3 S1000 means at least 905 rpm: first
// after cycle s + 90 (910 rpm; 900 after s + 89 is outside the band). The
// channel reads the status of the cycle before, so its wait ends in s + 91.
constexpr int kSpeedReachedAfter = 90;

// N1 M3 S1000 G1 X1 (default m3_sync MVS_SVS, not output): the block waits
// for speed reached from cycle 0, moves from cycle 91 on (cycles 91..100)
// and M30 runs in cycle 101.
TEST(ChannelSync, SpindleWaitEndsInTheCycleAfterSpeedReached) {
  KernelRig rig(spindle_machine());
  ASSERT_EQ(rig.k.spindle_count(), 1u);
  rig.push_block(0, move_with_m3(1, 1.0, 1000));
  rig.push_block(0, end_block(2));
  const Log r = run(rig.k, never());
  EXPECT_TRUE(r.issued.empty());
  int reached = -1;
  for (int i = 0; i < r.cycles() && reached < 0; ++i)
    if (r.speed_reached[static_cast<std::size_t>(i)]) reached = i;
  EXPECT_EQ(reached, kSpeedReachedAfter);
  const auto waits = r.of<kernel::ev::Wait>();
  const auto ends = r.of<kernel::ev::WaitEnd>();
  ASSERT_EQ(waits.size(), 1u);
  ASSERT_EQ(ends.size(), 1u);
  EXPECT_EQ(cycle_of(waits[0].t_s), 0);
  EXPECT_EQ(waits[0].reason, WaitReason::speed_reached);
  EXPECT_EQ(waits[0].spindle, std::optional<std::int8_t>(0));
  EXPECT_EQ(waits[0].fn, plc::TechKind::m);
  EXPECT_EQ(waits[0].number, 3);
  EXPECT_EQ(cycle_of(ends[0].t_s), kSpeedReachedAfter + 1);
  EXPECT_EQ(r.motion_start(), kSpeedReachedAfter + 1);
  EXPECT_EQ(cycle_of(r.of<kernel::ev::End>().at(0).t_s), kSpeedReachedAfter + 1 + kOneMm);
}

// M3 with PLC_INFO is output and waits for the PLC, with m3_prozess_zeit
// 5 ms as its acknowledgement timeout. N1 G1 X1 takes cycles 0..9; N2
// M3 S1000 G1 X2 starts in cycle 10: output, wait, deadline 10 + 5 ms.
Log timeout_run(const AckPolicy& plc) {
  config::Machine m = spindle_machine();
  m.channels[0].spindles[0].m3_sync = sync::MVS_SVS | sync::PLC_INFO;
  m.channels[0].spindles[0].m3_ack_timeout_s = 0.005;
  KernelRig rig(m);
  rig.push_block(0, move(1, nc::Motion::linear, 1.0));
  rig.push_block(0, move_with_m3(2, 2.0, 1000));
  rig.push_block(0, end_block(3));
  return run(rig.k, plc);
}

// Never acknowledged: PlcAckTimeout in cycle 15 (t = 15 ms >= the deadline),
// not before; the channel aborts there without moving on.
TEST(ChannelSync, UnacknowledgedOutputTimesOutAtItsDeadline) {
  const Log r = timeout_run(never());
  ASSERT_EQ(r.issued.size(), 1u);
  EXPECT_EQ(r.issued[0].cycle, kOneMm);
  EXPECT_EQ(r.issued[0].output.number, 3);
  EXPECT_EQ(r.issued[0].output.value, 1000.0);
  const auto errors = r.of<kernel::ev::Error>();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].id, ErrorId::PlcAckTimeout);
  EXPECT_EQ(errors[0].at.line, 2u);
  EXPECT_EQ(cycle_of(errors[0].t_s), kOneMm + 5);
  EXPECT_EQ(r.cycles(), kOneMm + 6);  // done after cycle 15
  EXPECT_EQ(r.status[kOneMm + 4], ChannelStatus::waiting);
  EXPECT_EQ(r.status.back(), ChannelStatus::aborted);
  EXPECT_DOUBLE_EQ(r.x.back(), 1.0);
}

// Acknowledged in cycle 14, one cycle before the deadline: no timeout. The
// wait's reason changes there from the PLC to the speed (wait_end, then a
// new wait); the spindle, started in cycle 10, reaches its speed after
// cycle 100, so N2 moves from cycle 101.
TEST(ChannelSync, AcknowledgedInTimeThenWaitsForTheSpeed) {
  const Log r = timeout_run(after(4));
  EXPECT_TRUE(r.of<kernel::ev::Error>().empty());
  const auto waits = r.of<kernel::ev::Wait>();
  const auto ends = r.of<kernel::ev::WaitEnd>();
  ASSERT_EQ(waits.size(), 2u);
  ASSERT_EQ(ends.size(), 2u);
  EXPECT_EQ(cycle_of(waits[0].t_s), kOneMm);
  EXPECT_EQ(waits[0].reason, WaitReason::plc_ack);
  EXPECT_EQ(cycle_of(ends[0].t_s), 14);
  EXPECT_EQ(cycle_of(waits[1].t_s), 14);
  EXPECT_EQ(waits[1].reason, WaitReason::speed_reached);
  const int moves = kOneMm + kSpeedReachedAfter + 1;
  EXPECT_EQ(cycle_of(ends[1].t_s), moves);
  EXPECT_DOUBLE_EQ(r.x[static_cast<std::size_t>(moves - 1)], 1.0);
  EXPECT_NEAR(r.x[static_cast<std::size_t>(moves)], 1.0 + kStep_mm, 1e-12);
  EXPECT_EQ(r.of<kernel::ev::End>().at(0).reason, EndReason::m30);
}

// --- programmed stops -----------------------------------------------------

// N1 M1, N2 M0, N3 M30, all without duration (cycle 0). M0 always reports a
// stop; M1 only while the HLI's optional-stop switch is on.
std::vector<std::uint32_t> stop_lines(bool optional_stop_switch) {
  KernelRig rig(fast_machine());
  nc::Block m1 = nop(1), m0 = nop(2);
  m1.m = {1};
  m1.optional_stop = true;
  m0.m = {0};
  m0.stop = true;
  rig.push_block(0, m1);
  rig.push_block(0, m0);
  rig.push_block(0, end_block(3));
  TickInput in;
  in.channels[0].optional_stop = optional_stop_switch;
  in.channels[0].cycle_start = true;  // the operator releases each hold at once
  const Log r = run(rig.k, never(), 10, in);
  EXPECT_TRUE(r.issued.empty());  // M0/M1 are not PLC outputs
  std::vector<std::uint32_t> lines;
  for (const auto& e : r.of<kernel::ev::Stop>()) lines.push_back(e.at.line);
  return lines;
}

TEST(ChannelSync, M1StopsOnlyWithTheOptionalStopSwitchM0Always) {
  EXPECT_EQ(stop_lines(false), (std::vector<std::uint32_t>{2}));
  EXPECT_EQ(stop_lines(true), (std::vector<std::uint32_t>{1, 2}));
}

// Without a cycle start the channel holds after M0 and starts no further block.
TEST(ChannelSync, M0HoldsUntilCycleStart) {
  KernelRig rig(fast_machine());
  nc::Block m0 = nop(1);
  m0.m = {0};
  m0.stop = true;
  rig.push_block(0, m0);
  rig.push_block(0, end_block(2));
  TickInput in;
  TickOutput out;
  for (int i = 0; i < 100; ++i) rig.k.tick(in, out);
  EXPECT_EQ(rig.k.program_state(0), ProgramState::hold);
  EXPECT_FALSE(rig.k.channel_done(0));
  in.channels[0].cycle_start = true;
  rig.k.tick(in, out);
  EXPECT_TRUE(rig.k.channel_done(0));  // released: M30 ran in the same cycle
  EXPECT_EQ(rig.k.program_state(0), ProgramState::ended);
}

// --- the bound on outstanding outputs -------------------------------------

// N1..N8 carry M100..M107 (MOS) each: 64 outputs in cycle 0, none waited
// for. N9 dwells 2 ms (cycles 0 and 1), so N10's M100 goes out in cycle 2
// as the 65th output. Without any acknowledgement it finds 64 outstanding:
// PlcOutputQueueFull at N10 in cycle 2. One acknowledgement in cycle 1
// leaves 63, and the 65th output goes out.
Log queue_run(const AckPolicy& plc) {
  config::Machine machine = fast_machine();
  for (int m = 100; m < 108; ++m) machine.channels[0].m_synch[static_cast<std::size_t>(m)] = sync::MOS;
  KernelRig rig(machine);
  for (std::uint32_t line = 1; line <= 8; ++line)
    rig.push_block(0, with_m(nop(line), {100, 101, 102, 103, 104, 105, 106, 107}));
  nc::Block dwell = nop(9);
  dwell.dwell_s = 0.002;
  rig.push_block(0, dwell);
  rig.push_block(0, with_m(nop(10), {100}));
  rig.push_block(0, end_block(11));
  return run(rig.k, plc, 100);
}

TEST(ChannelSync, SixtyFifthOutstandingOutputIsQueueFull) {
  static_assert(kMaxPendingOutputs == 64);
  const Log r = queue_run(never());
  ASSERT_EQ(r.issued.size(), 64u);
  EXPECT_EQ(r.issued.back().cycle, 0);
  const auto errors = r.of<kernel::ev::Error>();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].id, ErrorId::PlcOutputQueueFull);
  EXPECT_EQ(errors[0].at.line, 10u);
  EXPECT_EQ(cycle_of(errors[0].t_s), 2);
  EXPECT_EQ(r.of<kernel::ev::End>().at(0).reason, EndReason::error);
  EXPECT_EQ(r.status.back(), ChannelStatus::aborted);
}

TEST(ChannelSync, AnAcknowledgementMakesRoomForTheSixtyFifthOutput) {
  bool first = true;  // the PLC acknowledges the first output only, in cycle 1
  const Log r = queue_run([&first](const Issued&) { return std::exchange(first, false) ? 1 : -1; });
  ASSERT_EQ(r.issued.size(), 65u);
  EXPECT_EQ(r.issued.back().cycle, 2);
  EXPECT_EQ(r.issued.back().output.number, 100);
  EXPECT_TRUE(r.of<kernel::ev::Error>().empty());
  EXPECT_EQ(r.of<kernel::ev::End>().at(0).reason, EndReason::m30);
}

}  // namespace
}  // namespace nck::kernel
