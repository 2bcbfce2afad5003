// Single step (issue 27): a hold comes only at a block end the path reaches
// at standstill within its deceleration — never mid-block, never braking
// harder than a_max — also when the switch comes on while the path runs at
// speed through short blocks.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>

#include "test_machine.hpp"
#include "../seen_events.hpp"

namespace nck::kernel {
namespace {

using testing::end_block;
using testing::move;
using testing::xyz_machine;

constexpr double kAMax_mm_s2 = 2000;
constexpr int kChords = 60;
constexpr double kChord_mm = 2.0;

struct Rig {
  Rig() : m(std::make_unique<config::Machine>(xyz_machine(500, kAMax_mm_s2))) {
    for (auto& ax : m->axes)
      for (auto& g : ax.gears) g.accel_mm_s2 = g.decel_mm_s2 = 0.5 * kAMax_mm_s2;
    EXPECT_TRUE(k.configure(*m));
    prep.emplace(*m, 0, "", store, prep::PrepOptions{});
    // collinear 2 mm chords along X at F9000: planned to pass on at 150 mm/s
    for (int i = 0; i < kChords; ++i)
      EXPECT_TRUE(prep->prepare(move(static_cast<std::uint32_t>(i + 1), nc::Motion::linear, kChord_mm * (i + 1)),
                                k.commands(0)));
    EXPECT_TRUE(prep->prepare(end_block(kChords + 1), k.commands(0)));
  }
  std::unique_ptr<config::Machine> m;
  Kernel k;
  prep::PlanStore store;
  std::optional<prep::ChannelPrep> prep;
};

TEST(SingleStep, HoldsOnlyAtBlockEndsReachedAtStandstill) {
  Rig r;
  auto in = std::make_unique<TickInput>();
  auto out = std::make_unique<TickOutput>();
  const double dt = 0.001;
  double prev_x = 0, prev_v = 0, worst_a = 0;
  int holds = 0, held_cycles = 0;
  bool ended = false;
  for (int cycle = 0; cycle < 200000 && !ended; ++cycle) {
    // switched on at speed, in the middle of the run
    in->channels[0].single_step = cycle >= 60;
    in->channels[0].cycle_start = held_cycles == 5;  // the operator presses the button after 5 cycles
    r.k.tick(*in, *out);
    const double x = out->channels[0].axis_mcs[0];
    const double v = (x - prev_x) / dt;
    if (cycle > 0) worst_a = std::max(worst_a, std::abs(v - prev_v) / dt);
    prev_x = x;
    prev_v = v;
    bool held_now = false;
    for (const Event& e : out->events) {
      if (e.kind() == EventKind::end) ended = true;
      const auto* state = e.get<kernel::ev::State>();
      if (!state || state->to != ProgramState::hold) continue;
      EXPECT_EQ(state->reason, StateReason::single_step);
      // at a chord's end point, exactly
      EXPECT_NEAR(std::fmod(x, kChord_mm), 0.0, 1e-9) << "hold at X " << x;
      EXPECT_NEAR(x, kChord_mm * e.at.line, 1e-9);
      ++holds;
      held_now = true;
    }
    held_cycles = held_now ? 0 : (out->channels[0].program_state == ProgramState::hold ? held_cycles + 1 : -1);
    if (out->channels[0].program_state == ProgramState::hold && !held_now) {
      EXPECT_EQ(v, 0.0);  // it stands
    }
  }
  ASSERT_TRUE(ended);
  EXPECT_GE(holds, 40);  // nearly every chord after the switch
  EXPECT_LE(worst_a, kAMax_mm_s2 * (1 + 1e-6));
  EXPECT_NEAR(prev_x, kChord_mm * kChords, 1e-9);
}

}  // namespace
}  // namespace nck::kernel
