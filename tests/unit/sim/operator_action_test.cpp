// Operator actions on a running kernel (nck serve, the Python session): one
// scenario line without its time, parsed and checked as a scenario file's,
// applied by the simulated machine in the next cycle (MDI: by preparation).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "nck/config/load.hpp"
#include "nck/sim/dry_run.hpp"
#include "nck/sim/operator_action.hpp"
#include "scenario_fixture.hpp"

namespace nck::sim {
namespace {

std::optional<OperatorAction> parse(std::string_view line, Diagnostics& d) {
  static const config::Machine m = testing::machine();
  return parse_operator_action(line, m, d, "api");
}

TEST(OperatorAction, ReadsAScenarioLineWithoutItsTime) {
  Diagnostics d;
  auto op = parse("feed_override 80", d);
  ASSERT_TRUE(op) << d.items().at(0).message;
  EXPECT_EQ(op->action.kind(), ActionKind::feed_override);
  EXPECT_DOUBLE_EQ(op->action.get<act::FeedOverride>()->percent, 80);
  op = parse("ch=2 override S3 50", d);
  ASSERT_TRUE(op);
  EXPECT_EQ(op->action.channel, 2);
  EXPECT_EQ(op->action.get<act::SpindleOverride>()->spindle.hli, 2);  // resolved against the machine
  op = parse("mdi G0 X10 F1000", d);
  ASSERT_TRUE(op);
  EXPECT_EQ(op->action.kind(), ActionKind::mdi);
  EXPECT_EQ(op->mdi_text, "G0 X10 F1000");
  EXPECT_TRUE(d.items().empty());
}

TEST(OperatorAction, RefusesWhatIsNoLiveActionWithItsId) {
  const auto refused = [](std::string_view line) {
    Diagnostics d;
    EXPECT_FALSE(parse(line, d)) << line;
    EXPECT_EQ(d.items().size(), 1u) << line;
    EXPECT_TRUE(d.items().at(0).loc.file.empty()) << line;  // an action has no file: no placeholder
    EXPECT_EQ(d.items().at(0).loc.line, 0u) << line;
    return d.items().at(0).id;
  };
  EXPECT_EQ(refused("block_search N100"), ErrorId::PlcOperatorActionNotLive);
  // the scenario grammar's own IDs, not 960040 with them in the text (issue 47 item 5)
  EXPECT_EQ(refused("5 cycle_start"), ErrorId::PlcScenarioUnknownAction);  // a time is not part of it
  EXPECT_EQ(refused("@hold cycle_start"), ErrorId::PlcScenarioUnknownAction);
  EXPECT_EQ(refused("ch=3 feedhold on"), ErrorId::PlcScenarioBadChannel);  // no channel 3
  EXPECT_EQ(refused("override S9 50"), ErrorId::PlcScenarioUnknownSpindle);
  EXPECT_EQ(refused("feed_override 80\n1 reset"), ErrorId::PlcOperatorActionBad);
  EXPECT_EQ(refused(""), ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(refused("launch rockets"), ErrorId::PlcScenarioUnknownAction);
}

// A typed action (nck serve, the Python session) is checked and resolved
// as its scenario line would be, and refused with the same words.
TEST(OperatorAction, TypedActionsAreCheckedAsTheirLines) {
  static const config::Machine m = testing::machine();
  const auto checked = [&](const ScenarioAction& a, Diagnostics& d) {
    return check_operator_action(OperatorAction{a, {}}, m, d, "api");
  };
  act::SpindleOverride o;
  o.spindle.name = {'S', '3'};
  o.percent = 50;
  Diagnostics d;
  auto op = checked(make_action(2, o), d);
  ASSERT_TRUE(op);
  EXPECT_EQ(op->action.get<act::SpindleOverride>()->spindle.hli, 2);
  EXPECT_EQ(operator_line(*op, Quoting::api), "ch=2 spindle_override S3 50");
  act::Jog j;
  j.axis.name = {'Q'};
  j.direction = 1;
  j.speed_mm_min = 600;
  Diagnostics refused;
  EXPECT_FALSE(checked(make_action(1, j), refused));
  Diagnostics same;
  EXPECT_FALSE(parse_operator_action("ch=1 jog Q + 600", m, same, "api"));
  ASSERT_EQ(refused.items().size(), 1u);
  EXPECT_EQ(refused.items()[0].id, ErrorId::PlcScenarioUnknownAxis);
  EXPECT_EQ(refused.items()[0].id, same.items().at(0).id);
  EXPECT_EQ(refused.items()[0].message, same.items().at(0).message);
  o.spindle.name = {'X', '1'};
  Diagnostics bad_name, bad_line;
  EXPECT_FALSE(checked(make_action(1, o), bad_name));
  EXPECT_FALSE(parse_operator_action("ch=1 spindle_override X1 50", m, bad_line, "api"));
  EXPECT_EQ(bad_name.items().at(0).message, bad_line.items().at(0).message);
  Diagnostics search;
  EXPECT_FALSE(checked(make_action(1, act::BlockSearch{}), search));
  EXPECT_EQ(search.items().at(0).id, ErrorId::PlcOperatorActionNotLive);
}

// A dry run of examples/mill/contour.nc operated by hand.
struct LiveMill {
  std::unique_ptr<config::Machine> machine;
  std::optional<DryRun> run;
  kernel::TickOutput out;

  explicit LiveMill(bool with_program, bool threaded = false) {
    const std::string root = NCK_SOURCE_DIR;
    config::LoadResult loaded = config::load_machine(root + "/examples/mill");
    machine = std::make_unique<config::Machine>(*loaded.machine);
    std::vector<std::filesystem::path> programs;
    if (with_program) programs.emplace_back(root + "/examples/mill/contour.nc");
    DryRunOptions options;
    options.prep_thread = threaded;
    run.emplace(*DryRun::create(*machine, programs, options));
  }
  std::optional<Diagnostic> operate(std::string_view line) {
    Diagnostics d;
    auto op = parse_operator_action(line, *machine, d);
    EXPECT_TRUE(op) << line;
    return run->operate(*op);
  }
  void cycles(int n) {
    for (int i = 0; i < n; ++i) run->step(out);
  }
};

TEST(OperatorAction, FeedholdStopsTheRunningPathAndReleases) {
  LiveMill mill(true);
  mill.cycles(3000);
  ASSERT_GT(mill.out.channels[0].path_velocity_mm_s, 1.0);
  EXPECT_FALSE(mill.operate("feedhold on"));
  mill.cycles(1500);
  EXPECT_EQ(mill.out.channels[0].path_velocity_mm_s, 0.0);
  EXPECT_FALSE(mill.operate("feedhold off"));
  mill.cycles(1500);
  EXPECT_GT(mill.out.channels[0].path_velocity_mm_s, 1.0);
}

// The live state's distance to go: the rest of the running motion, shrinking
// by the path's travel each cycle.
TEST(OperatorAction, DistanceToGoShrinksByTheTravel) {
  LiveMill mill(true);
  mill.cycles(3000);
  const double before_mm = mill.out.channels[0].distance_to_go_mm;
  mill.cycles(1);
  const kernel::ChannelOutput& now = mill.out.channels[0];
  ASSERT_GT(now.path_velocity_mm_s, 1.0);
  ASSERT_GT(now.distance_to_go_mm, 0.0);
  EXPECT_NEAR(before_mm - now.distance_to_go_mm, now.path_velocity_mm_s * 0.001, 1e-3 * now.path_velocity_mm_s * 0.001 + 1e-9);
}

TEST(OperatorAction, MdiMovesAnIdleChannelAndIsRefusedWhileAProgramRuns) {
  LiveMill idle(false);
  idle.cycles(2);
  EXPECT_FALSE(idle.operate("mdi G0 X10"));
  idle.cycles(5000);
  EXPECT_NEAR(idle.out.channels[0].axis_mcs[0], 10.0, 1e-9);

  LiveMill busy(true);
  busy.cycles(100);
  const auto refused = busy.operate("mdi G0 X10");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->id, ErrorId::KernelMdiRefused);
}

// A program reset in the middle: the channel is idle, and MDI runs from
// where the axes stand (single and threaded preparation).
TEST(OperatorAction, MdiRunsAfterAResetInTheMiddleOfAProgram) {
  for (const bool threaded : {false, true}) {
    LiveMill mill(true, threaded);
    mill.cycles(3000);
    EXPECT_FALSE(mill.operate("reset"));
    mill.cycles(200);
    ASSERT_EQ(mill.run->kernel().program_state(0), kernel::ProgramState::idle) << threaded;
    const AxisArray stopped = mill.out.channels[0].axis_mcs;
    EXPECT_FALSE(mill.operate("mdi G0 X10"));
    double largest_step_mm = 0;
    for (int i = 0; i < 5000; ++i) {
      const AxisArray before = mill.out.channels[0].axis_mcs;
      mill.cycles(1);
      for (std::size_t j = 0; j < 3; ++j)
        largest_step_mm = std::max(largest_step_mm, std::abs(mill.out.channels[0].axis_mcs[j] - before[j]));
    }
    EXPECT_NEAR(mill.out.channels[0].axis_mcs[0], 10.0, 1e-9) << threaded;
    // from where the path stood: Y and Z stay, and no axis jumps (at most a rapid's travel per cycle)
    EXPECT_NEAR(mill.out.channels[0].axis_mcs[1], stopped[1], 1e-9) << threaded;
    EXPECT_NEAR(mill.out.channels[0].axis_mcs[2], stopped[2], 1e-9) << threaded;
    EXPECT_LE(largest_step_mm, 0.5 + 1e-9) << threaded;  // the mill's rapids: 30 m/min = 0.5 mm per cycle
  }
}

// A live run starts with the operator's block-skip levels: preparation,
// which decodes before the first cycle, skips from the first block on.
TEST(OperatorAction, ARunStartsWithTheSkipLevelsItIsGiven) {
  const std::filesystem::path program = std::filesystem::temp_directory_path() / "nck_skip_start.nc";
  std::ofstream(program) << "N10 G0 X5\n/N20 G0 X50\nN30 M30\n";
  const std::string root = NCK_SOURCE_DIR;
  config::LoadResult loaded = config::load_machine(root + "/examples/mill");
  for (const bool threaded : {false, true}) {
    DryRunOptions options;
    options.prep_thread = threaded;
    options.skip_masks[0] = 0x1;
    auto run = DryRun::create(*loaded.machine, {program}, options);
    ASSERT_TRUE(run);
    if (threaded) run->start_preparation_thread();
    kernel::TickOutput out;
    double largest_x = 0;
    for (int i = 0; i < 3000 && !run->done(); ++i) {
      run->step(out);
      largest_x = std::max(largest_x, out.channels[0].axis_mcs[0]);
    }
    EXPECT_NEAR(largest_x, 5.0, 1e-9) << threaded;  // /N20 skipped
    EXPECT_EQ(run->machine().hli().channel[0].skip_mask, 0x1u);
  }
  std::filesystem::remove(program);
}

TEST(OperatorAction, AtMost32ActionsWaitForOneCycle) {
  LiveMill mill(true);
  for (int i = 0; i < 32; ++i) EXPECT_FALSE(mill.operate("feed_override 50"));
  const auto full = mill.operate("feed_override 60");
  ASSERT_TRUE(full);
  EXPECT_EQ(full->id, ErrorId::PlcOperatorActionsFull);
  mill.cycles(1);  // the cycle takes them all: room again
  EXPECT_FALSE(mill.operate("feed_override 60"));
}

}  // namespace
}  // namespace nck::sim
