#include <gtest/gtest.h>

#include <memory>

#include "scenario_fixture.hpp"
#include "nck/sim/machine_sim.hpp"
#include "nck/sim/scenario_player.hpp"

namespace nck::sim {
namespace {

using sim::ActionKind;
using sim::testing::Fixture;

TEST(ScenarioPlayer, YieldsDueActionsOnceAtTheirCycle) {
  Fixture f("0.002 reset\n0.0005 feedhold on\n0.002 feedhold off\n0.010 silent on\n");
  ASSERT_FALSE(f.diags.has_errors());  // only the "time goes backwards" warning
  ScenarioPlayer p(f.sc);
  int seen = 0;
  std::vector<std::pair<int, ActionKind>> log;
  for (int k = 0; k <= 12; ++k) {
    for (const auto& a : p.due(k * 0.001)) {
      log.emplace_back(k, a.kind());
      ++seen;
    }
  }
  ASSERT_EQ(seen, 4);
  EXPECT_EQ(log[0], std::make_pair(1, ActionKind::feedhold));
  EXPECT_EQ(log[1], std::make_pair(2, ActionKind::reset));
  EXPECT_EQ(log[2], std::make_pair(2, ActionKind::feedhold));
  EXPECT_EQ(log[3], std::make_pair(10, ActionKind::silent));
  EXPECT_TRUE(p.finished());
  EXPECT_TRUE(p.due(100.0).empty());
  p.rewind();
  EXPECT_EQ(p.due(0.002).size(), 3u);
}

TEST(ScenarioPlayer, EmptyPlayerIsHarmless) {
  ScenarioPlayer p;
  EXPECT_TRUE(p.due(1.0).empty());
  EXPECT_TRUE(p.finished());
}

// The scenario's actions as the kernel sees them after one read().
struct Applied {
  explicit Applied(Fixture& f) : sim(f.m) {
    sim.load_scenario(f.sc);
    sim.read(0.0, *in);
  }
  MachineSim sim;
  std::unique_ptr<kernel::TickInput> in = std::make_unique<kernel::TickInput>();
};

TEST(MachineSim, ScenarioWritesHliControlObjects) {
  Fixture f(
      "0 override S1 50\n0 ch=2 feed_override 80\n0 feedhold on\n0 spindle_feedhold S2 on\n"
      "0 ch=2 spindle_stop_at_end on\n0 spindle_reset S1\n0 optional_stop on\n0 reset\n"
      "0 override_valid S2 off\n");
  ASSERT_TRUE(f.diags.empty());
  Applied a(f);
  const plc::HliImage& hli = a.sim.hli();
  const kernel::TickInput& in = *a.in;
  EXPECT_DOUBLE_EQ(hli.spindle_control[0].override_percent, 50);
  EXPECT_DOUBLE_EQ(in.spindles[0].effective_override_percent(), 50);
  EXPECT_DOUBLE_EQ(in.channels[1].feed_override_pct, 80);
  EXPECT_DOUBLE_EQ(in.channels[0].feed_override_pct, 100);
  EXPECT_TRUE(in.channels[0].feedhold);
  EXPECT_TRUE(in.spindles[1].feedhold);
  EXPECT_FALSE(in.spindles[0].feedhold);
  EXPECT_TRUE(in.spindles[2].stop_at_program_end);  // S3, channel 2
  EXPECT_FALSE(in.spindles[0].stop_at_program_end);
  EXPECT_TRUE(in.channels[0].optional_stop);
  EXPECT_FALSE(in.spindles[1].override_valid);
  // Resets are requests: handed to the kernel once, then cleared.
  EXPECT_TRUE(in.spindles[0].reset);
  EXPECT_TRUE(in.channels[0].reset);
  EXPECT_FALSE(in.channels[1].reset);
  a.sim.read(0.001, *a.in);
  EXPECT_FALSE(a.in->spindles[0].reset);
  EXPECT_FALSE(a.in->channels[0].reset);
}

TEST(MachineSim, SilentPlcAcknowledgesNothing) {
  Fixture f("0 silent on\n1 silent off\n");
  Applied a(f);
  auto out = std::make_unique<kernel::TickOutput>();
  plc::TechOutput o;
  o.number = 100;
  ASSERT_TRUE(out->tech_outputs.push_back(kernel::TechRequest{7, o}));
  a.sim.write(*out);
  a.sim.read(0.5, *a.in);
  EXPECT_TRUE(a.in->acks.empty());
  a.sim.read(1.0, *a.in);  // silent off: the overdue output is acknowledged
  ASSERT_EQ(a.in->acks.size(), 1u);
  EXPECT_EQ(a.in->acks[0].handle, 7u);
}

TEST(MachineSim, ExternalCommandsArriveInFileOrder) {
  Fixture f("0 spindle_cmd S2 M3 REV500\n0 spindle_cmd S1 M19 POS90 REV100\n0 spindle_cmd S2 M5\n");
  ASSERT_TRUE(f.diags.empty());
  Applied a(f);
  ASSERT_EQ(a.in->ext_commands.size(), 3u);
  EXPECT_EQ(a.in->ext_commands[0].spindle, 1);
  EXPECT_EQ(a.in->ext_commands[0].fn, plc::ExtFunction::m3);
  EXPECT_EQ(a.in->ext_commands[1].spindle, 0);
  EXPECT_EQ(a.in->ext_commands[1].fn, plc::ExtFunction::m19);
  EXPECT_DOUBLE_EQ(a.in->ext_commands[1].pos_deg, 90);
  EXPECT_EQ(a.in->ext_commands[2].fn, plc::ExtFunction::m5);
  EXPECT_EQ(a.in->ext_commands_lost, 0u);
  a.sim.read(0.001, *a.in);  // delivered once
  EXPECT_TRUE(a.in->ext_commands.empty());
}

TEST(MachineSim, MoreExternalCommandsThanFitAreCountedNotDropped) {
  std::string text;
  for (std::size_t i = 0; i < plc::ExtCommandQueue::kCapacity + 3; ++i) text += "0 spindle_cmd S1 M3 REV1\n";
  Fixture f(text);
  Applied a(f);
  EXPECT_EQ(a.in->ext_commands.size(), plc::ExtCommandQueue::kCapacity);
  EXPECT_EQ(a.in->ext_commands_lost, 3u);
}

}  // namespace
}  // namespace nck::sim
