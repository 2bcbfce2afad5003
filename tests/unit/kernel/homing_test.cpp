// Homing and P-AXIS-00277 (kenngr.prog_move_requires_homing): a programmed
// motion of an unhomed axis that requires homing is refused before
// anything moves (930740, naming the axis, at the block's line); G74 homes
// the axes it names; an axis without the setting moves unhomed; the homed
// state goes on into the next run of a live session (DryRun::carry_homing).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <memory>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "nck/config/load.hpp"
#include "nck/sim/dry_run.hpp"
#include "../seen_events.hpp"

namespace nck::kernel {
namespace {

namespace fs = std::filesystem;

const fs::path kMachine = fs::path(NCK_SOURCE_DIR) / "tests/data/machine_homing";

struct Ran {
  std::vector<Event> events;
  std::unique_ptr<sim::DryRun> run;
  AxisArray max_abs_mcs{};  // per axis: the farthest it stood from 0 in any cycle
};

// Runs `program` (a file of the test machine, or text written to a file)
// to its end; homed: the axes homed at its start (none: all, as nck run).
Ran run_program(const std::string& text, std::optional<std::uint32_t> homed) {
  config::LoadResult loaded = config::load_machine(kMachine);
  EXPECT_TRUE(loaded.ok());
  const fs::path file = fs::temp_directory_path() / ("nck_homing_" + std::to_string(::getpid()) + ".nc");
  { std::FILE* f = std::fopen(file.c_str(), "w"); std::fputs(text.c_str(), f); std::fclose(f); }
  sim::DryRunOptions o;
  o.homed_axes[0] = homed;
  auto run = sim::DryRun::create(*loaded.machine, {file}, o);
  EXPECT_TRUE(run.has_value());
  Ran r;
  r.run = std::make_unique<sim::DryRun>(std::move(*run));
  auto out = std::make_unique<TickOutput>();
  for (int i = 0; i < 200000 && !r.run->done(); ++i) {
    r.run->step(*out);
    r.events.insert(r.events.end(), out->events.begin(), out->events.end());
    for (std::size_t j = 0; j < 3; ++j)
      r.max_abs_mcs[j] = std::max(r.max_abs_mcs[j], std::abs(out->channels[0].axis_mcs[j]));
  }
  fs::remove(file);
  return r;
}

std::vector<test::Seen<ev::Error>> errors(const Ran& r) { return test::seen<ev::Error>(r.events); }

TEST(Homing, UnhomedAxisThatRequiresHomingIsRefusedBeforeItMoves) {
  const Ran r = run_program("G90 G0 Y10\nG0 X20 Y10\nM30\n", 0u);
  const auto e = errors(r);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].id, ErrorId::KernelAxisNotHomed);
  EXPECT_EQ(e[0].at.line, 2u);  // the block's line
  ASSERT_TRUE(e[0].message.has_value());
  EXPECT_NE(r.run->message(*e[0].message).find("axis X is not homed"), std::string::npos);
  EXPECT_EQ(r.max_abs_mcs[0], 0.0);   // X never moved
  EXPECT_EQ(r.max_abs_mcs[1], 10.0);  // Y (no P-AXIS-00277) moved unhomed
  EXPECT_EQ(r.run->kernel().program_state(0), ProgramState::error);
  EXPECT_EQ(r.run->kernel().channel_state(0).homed_axes, 0u);
  EXPECT_EQ(r.run->kernel().channel_state(0).homing_required, 0b101u);  // X and Z
}

TEST(Homing, G74HomesThenTheMoveRuns) {
  const Ran r = run_program("G90 G74 X1 Z2\nG0 X20 Z5\nM30\n", 0u);
  EXPECT_TRUE(errors(r).empty());
  const ChannelState st = r.run->kernel().channel_state(0);
  EXPECT_EQ(st.homed_axes & 0b101u, 0b101u);
  EXPECT_DOUBLE_EQ(st.axis_mcs[0], 20.0);
  EXPECT_DOUBLE_EQ(st.axis_mcs[2], 5.0);
  EXPECT_EQ(r.run->kernel().program_state(0), ProgramState::ended);
}

TEST(Homing, G74OfOneAxisLeavesTheOtherUnhomed) {
  const Ran r = run_program("G90 G74 X1\nG0 X20\nG0 Z5\nM30\n", 0u);
  const auto e = errors(r);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].id, ErrorId::KernelAxisNotHomed);
  EXPECT_EQ(e[0].at.line, 3u);
  EXPECT_NE(r.run->message(*e[0].message).find("axis Z"), std::string::npos);
  EXPECT_EQ(r.max_abs_mcs[2], 0.0);
  EXPECT_DOUBLE_EQ(r.run->kernel().channel_state(0).axis_mcs[0], 20.0);
}

TEST(Homing, ACircleThatEndsWhereItStartsStillMovesItsAxes) {
  // Y is homed by nothing and needs nothing; X requires homing: a full
  // circle in G17 moves X although its end equals its start.
  const Ran r = run_program("G90 G17 G0 Y10\nG2 J-10 F1000\nM30\n", 0b010u);
  const auto e = errors(r);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].at.line, 2u);
  EXPECT_EQ(r.max_abs_mcs[0], 0.0);
}

TEST(Homing, TheDryRunAssumesAHomedMachine) {
  const Ran r = run_program("G90 G0 X20 Z5\nM30\n", std::nullopt);
  EXPECT_TRUE(errors(r).empty());
  EXPECT_EQ(r.run->kernel().channel_state(0).homed_axes, ~0u);
}

TEST(Homing, MdiIsCheckedLikeAProgramAndTheHomedStateGoesOnIntoTheNextRun) {
  Ran first = run_program("G90 G74 X1 Z1\nM30\n", 0u);
  ASSERT_EQ(first.run->kernel().channel_state(0).homed_axes, 0b101u);
  config::LoadResult loaded = config::load_machine(kMachine);
  sim::DryRunOptions o;
  o.homed_axes[0] = 0u;  // made before the G74 (a staged run): the swap hands the state on
  auto next = sim::DryRun::create(*loaded.machine, {}, o);
  ASSERT_TRUE(next.has_value());
  next->carry_homing(*first.run);
  EXPECT_EQ(next->kernel().channel_state(0).homed_axes, 0b101u);
  // MDI on an unhomed machine: refused like a program's block.
  auto fresh = sim::DryRun::create(*loaded.machine, {}, o);
  ASSERT_TRUE(fresh.has_value());
  EXPECT_FALSE(fresh->mdi(0, "G0 X5", ProgramState::idle, SourceLoc{}).has_value());
  auto out = std::make_unique<TickOutput>();
  std::vector<Event> seen;
  for (int i = 0; i < 3000; ++i) {
    fresh->step(*out);
    seen.insert(seen.end(), out->events.begin(), out->events.end());
    EXPECT_EQ(out->channels[0].axis_mcs[0], 0.0);
  }
  const auto e = test::seen<ev::Error>(seen);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].id, ErrorId::KernelAxisNotHomed);
  EXPECT_EQ(fresh->kernel().program_state(0), ProgramState::idle);  // MDI's error leaves the channel usable
}

}  // namespace
}  // namespace nck::kernel
