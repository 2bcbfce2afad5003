// The velocity look-ahead: programs planned for the mill example (X/Y
// a_max 3000, accel_mm_s2 = decel_mm_s2 2500 mm/s^2: a kink may change an axis's
// velocity by 0.5 mm/s per 1 ms cycle), pushed through the window; the
// velocities at the block ends are checked against hand-worked limits.
// Each test plans with a new rig: a planner remembers where the axes are.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "example_blocks.hpp"
#include "nck/motion/junction.hpp"
#include "nck/motion/path_profile.hpp"
#include "nck/prep/lookahead_window.hpp"
#include "nck/prep/planner.hpp"

namespace nck::prep {
namespace {

using testing::decode_blocks;
using testing::example_machine;

struct Rig {
  explicit Rig(std::size_t depth = 120)
      : machine(example_machine("mill")), planner(machine, 0, store, PlannerOptions{}, {0, 1}), window(depth, 0.001) {}

  // Plans the program into the window and flushes it; the queued commands in order.
  std::vector<kernel::Command> run(const std::string& text) {
    std::vector<kernel::Command> out;
    auto drain = [&] {
      while (!queue.empty()) {
        out.push_back(queue.front());
        queue.pop();
      }
    };
    for (const nc::Block& b : decode_blocks(machine, text)) {
      while (!window.push(planner.plan(b))) {
        (void)window.release(queue, false);
        drain();
      }
      while (!window.release(queue, b.program_end)) drain();
      drain();
    }
    while (!window.release(queue, true)) drain();
    drain();
    return out;
  }
  // The fastest the path may pass each motion command's end, in order: its
  // v_end, or (braking across it) the staircase's speed there if lower.
  std::vector<double> ends(const std::string& text) {
    std::vector<double> v;
    for (const kernel::Command& c : run(text))
      if (const auto* m = c.as<kernel::Motion>()) v.push_back(passing(*m));
    return v;
  }
  static double passing(const kernel::Motion& m) {
    if (!(m.brake_beyond_mm > 0)) return m.v_end_mm_s;
    return std::min(m.v_end_mm_s, motion::discrete_brake_velocity(m.brake_beyond_mm, m.limits.a_dec_mm_s2, 0.001));
  }

  const config::Machine& machine;
  PlanStore store;
  Planner planner;
  LookAheadWindow window;
  kernel::CommandQueue queue;
};

TEST(LookAhead, CollinearChordsRunThroughAtFeedAndStopAtTheEnd) {
  Rig r;
  // F1200 = 20 mm/s; 2 mm chords are long enough to brake from 20 mm/s.
  const auto v = r.ends("N10 G1 X2 F1200\nN20 X4\nN30 X6\nN40 X8\nN50 M30\n");
  ASSERT_EQ(v.size(), 4u);
  EXPECT_DOUBLE_EQ(v[0], 20.0);
  EXPECT_DOUBLE_EQ(v[1], 20.0);
  EXPECT_DOUBLE_EQ(v[2], 20.0);
  EXPECT_EQ(v[3], 0.0);
}

TEST(LookAhead, KinksArePassedAtTheirBudgetLessOneBrakingStep) {
  // 1:10 kink: from +X into (10, 1)/|..|: X turns by 1 - 10/sqrt(101), Y by
  // 1/sqrt(101). Y decides: passing at speed the kink may take half of
  // a_max (3,000 mm/s^2: 1.5 mm/s in a cycle, more than the 500 a_max
  // leaves above the feed's 2,500; issue 43), 1.5 / 0.0995 = 15.07 mm/s,
  // less one braking step along N10 (2500 mm/s^2 * 1 ms = 2.5 mm/s).
  const auto v = Rig().ends("N10 G1 X20 F1200\nN20 X30 Y1\nN30 M30\n");
  ASSERT_EQ(v.size(), 2u);
  EXPECT_NEAR(v[0], 1.5 * std::sqrt(101.0) - 2.5, 1e-9);
  // A right angle turns X and Y by 1: 1.5 mm/s is less than one braking
  // step, so the path stops there.
  EXPECT_EQ(Rig().ends("N10 G1 X20 F1200\nN20 Y20\nN30 M30\n").front(), 0.0);
}

TEST(LookAhead, ShortBlocksAtTheEndLowerTheTransitionsBeforeThem) {
  Rig r;
  // Three 0.01 mm chords before the stop: the transitions must allow braking.
  const auto v = r.ends("N10 G1 X10 F3000\nN20 X10.01\nN30 X10.02\nN40 X10.03\nN50 M30\n");
  ASSERT_EQ(v.size(), 4u);
  const double a = 2500, dt = 0.001;
  EXPECT_LT(v[2], motion::entry_velocity_limit(0.01, 0, a, dt) + 1e-9);
  EXPECT_LT(v[0], motion::entry_velocity_limit(0.03, 0, a, dt) + 1e-9);
  EXPECT_GT(v[0], 0.0);
  EXPECT_LT(v[0], 50.0);
}

// Blocks of two cycles' travel (0.1 mm at F3000 = 50 mm/s): holding every
// end speed would cost each block its margins (one cycle's travel, one
// braking step) and cap the path near 25 mm/s; braking across their ends
// (braking_staircase.hpp) lets every transition pass at the feed, and only
// the motions within braking distance of the stop brake across towards it.
TEST(LookAhead, ShortChordsBrakeAcrossTheirEndsAndRunAtFeed) {
  std::string program = "N1 G1 X0 F3000\n";
  for (int i = 1; i <= 200; ++i) program += "X" + std::to_string(0.1 * i) + "\n";
  program += "M30\n";
  Rig r;
  std::vector<const kernel::Motion*> motions;
  const std::vector<kernel::Command> commands = r.run(program);
  for (const kernel::Command& c : commands)
    if (const auto* m = c.as<kernel::Motion>()) motions.push_back(m);
  ASSERT_EQ(motions.size(), 200u);
  for (std::size_t i = 0; i + 1 < motions.size(); ++i) {
    EXPECT_DOUBLE_EQ(motions[i]->v_end_mm_s, 50.0) << i;
    EXPECT_GT(motions[i]->brake_beyond_mm, 0.0) << i;
  }
  EXPECT_EQ(motions.back()->v_end_mm_s, 0.0);
  // Far from the stop the staircase lies beyond the window's end; near it,
  // it ends where the last block stops.
  EXPECT_NEAR(motions[198]->brake_beyond_mm, 0.1, 1e-9);
}

TEST(LookAhead, LowerFeedIsReachedBeforeItsBlockAndHigherAfter) {
  Rig r;
  const auto v = r.ends("N10 G1 X10 F3000\nN20 X20 F600\nN30 X30 F3000\nN40 M30\n");
  ASSERT_EQ(v.size(), 3u);
  EXPECT_DOUBLE_EQ(v[0], 10.0);  // F600
  EXPECT_DOUBLE_EQ(v[1], 10.0);
}

TEST(LookAhead, ExactStopWhereTheProgramAsks) {
  Rig r;
  EXPECT_EQ(r.ends("N10 G1 X10 F1200\nN20 G60 X20\nN30 X30\nN40 M30\n"),
            (std::vector<double>{20.0, 0.0, 0.0}));
  Rig modal;
  EXPECT_EQ(modal.ends("N10 G1 X10 F1200\nN20 G360 X20\nN30 X30\nN40 G359 X40\nN50 X50\nN60 M30\n"),
            (std::vector<double>{20.0, 0.0, 0.0, 20.0, 0.0}));
}

TEST(LookAhead, FunctionsAndWaitsStopThePathButPlainBlocksDoNot) {
  // An F change alone: the path runs through.
  EXPECT_EQ(Rig().ends("N10 G1 X10 F1200\nN20 F1200\nN30 X20\nN40 M30\n"), (std::vector<double>{20.0, 0.0}));
  // An M function (output), a dwell, a spindle function: standstill around them.
  EXPECT_EQ(Rig().ends("N10 G1 X10 F1200\nN20 M8\nN30 X20\nN40 M30\n"), (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(Rig().ends("N10 G1 X10 F1200\nN20 G4 X0.1\nN30 X20\nN40 M30\n"), (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(Rig().ends("N10 G1 X10 F1200\nN20 X20 S1000 M3\nN30 X30\nN40 M30\n"),
            (std::vector<double>{0.0, 0.0, 0.0}));
}

TEST(LookAhead, ExactStopAfterG0WhenConfigured) {
  Rig r;
  EXPECT_EQ(r.ends("N10 G0 X10\nN20 G1 X20 F1200\nN30 M30\n").front(), 20.0);
  config::Machine m = example_machine("mill");
  m.channels[0].exact_stop_after_g00 = true;
  PlanStore store;
  Planner p(m, 0, store, PlannerOptions{}, {0, 1});
  std::vector<PlannedCommand> cs;
  for (const nc::Block& b : decode_blocks(m, "N10 G0 X10\nN20 G1 X20 F1200\nN30 M30\n"))
    for (const PlannedCommand& c : p.plan(b)) cs.push_back(c);
  EXPECT_TRUE(cs[0].exact_stop);
  EXPECT_FALSE(cs[1].exact_stop);
}

TEST(LookAhead, DepthZeroPassesEveryBlockOnAtOnceWithAStop) {
  Rig r(0);
  EXPECT_EQ(r.ends("N10 G1 X2 F1200\nN20 X4\nN30 M30\n"), (std::vector<double>{0.0, 0.0}));
}

}  // namespace
}  // namespace nck::prep
