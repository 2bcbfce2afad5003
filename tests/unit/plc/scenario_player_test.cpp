#include <gtest/gtest.h>

#include "nck/plc/scenario.hpp"

namespace nck::plc {
namespace {

config::Machine machine() {
  config::Machine m;
  m.channels.resize(2);
  auto& c1 = m.channels[0];
  c1.spindles.resize(2);
  c1.spindles[0].name = "S1";
  c1.spindles[0].log_axis_nr = 6;
  c1.spindles[1].name = "S2";
  c1.spindles[1].log_axis_nr = 7;
  c1.main_spindle_ax_nr = 7;  // "S" is S2 at start
  auto& c2 = m.channels[1];
  c2.number = 2;
  c2.spindles.resize(1);
  c2.spindles[0].name = "S3";
  c2.spindles[0].log_axis_nr = 8;
  c2.main_spindle_ax_nr = 8;
  return m;
}

struct Fixture {
  config::Machine m = machine();
  SpindleMap map = build_spindle_map(m);
  Diagnostics diags;
  Scenario sc;
  explicit Fixture(std::string_view text) {
    sc = parse_scenario(text, "t.plc", diags);
    resolve_spindles(sc, m, map, diags);
  }
};

TEST(ScenarioResolve, NamesBecomeIndices) {
  Fixture f("0 override S2 50\n0 ch=2 override S3 60\n0 override S 70\n0 spindle_cmd s1 M3 REV10\n");
  EXPECT_TRUE(f.diags.empty());
  ASSERT_EQ(f.sc.actions.size(), 4u);
  EXPECT_EQ(f.sc.actions[0].spindle, 1);
  EXPECT_EQ(f.sc.actions[0].hli_spindle, 1);
  EXPECT_EQ(f.sc.actions[1].spindle, 0);
  EXPECT_EQ(f.sc.actions[1].hli_spindle, 2);
  EXPECT_EQ(f.sc.actions[2].spindle, 1);  // main spindle of channel 1 = S2
  EXPECT_EQ(f.sc.actions[3].cmd.spindle, 0);
}

TEST(ScenarioResolve, UnknownSpindleOrChannelIsReportedWithLine) {
  Fixture f("0 reset\n0 override S9 50\n0 ch=3 reset\n0 ch=2 spindle_reset S1\n");
  ASSERT_EQ(f.diags.items().size(), 3u);
  EXPECT_EQ(f.diags.items()[0].id, ErrorId::PlcScenarioUnknownSpindle);
  EXPECT_EQ(f.diags.items()[0].loc.line, 2u);
  EXPECT_NE(f.diags.items()[0].message.find("S1, S2"), std::string::npos);
  EXPECT_EQ(f.diags.items()[1].id, ErrorId::PlcScenarioBadChannel);
  EXPECT_EQ(f.diags.items()[1].loc.line, 3u);
  EXPECT_EQ(f.diags.items()[2].id, ErrorId::PlcScenarioUnknownSpindle);
  EXPECT_EQ(f.diags.items()[2].loc.line, 4u);
  ASSERT_EQ(f.sc.actions.size(), 1u);
  EXPECT_EQ(f.sc.actions[0].kind, ActionKind::reset);
}

TEST(ScenarioPlayer, YieldsDueActionsOnceAtTheirCycle) {
  Fixture f("0.002 reset\n0.0005 feedhold on\n0.002 feedhold off\n0.010 silent on\n");
  ASSERT_FALSE(f.diags.has_errors());  // only the "time goes backwards" warning
  ScenarioPlayer p(f.sc);
  int seen = 0;
  std::vector<std::pair<int, ActionKind>> log;
  for (int k = 0; k <= 12; ++k) {
    for (const auto& a : p.due(k * 0.001)) {
      log.emplace_back(k, a.kind);
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

struct Runtime {
  HliImage hli;
  PlcSim plc{config::SimConfig{}};
  ExtCommandQueue ext;
};

void apply_all(Fixture& f, Runtime& rt) {
  for (const auto& a : f.sc.actions) EXPECT_EQ(apply(a, f.map, rt.hli, rt.plc, rt.ext), ApplyResult::ok);
}

TEST(ScenarioApply, WritesHliControlObjects) {
  Fixture f(
      "0 override S1 50\n0 ch=2 feed_override 80\n0 feedhold on\n0 spindle_feedhold S2 on\n"
      "0 ch=2 spindle_stop_at_end on\n0 spindle_reset S1\n0 optional_stop on\n0 reset\n"
      "0 override_valid S2 off\n");
  ASSERT_TRUE(f.diags.empty());
  Runtime rt;
  apply_all(f, rt);
  EXPECT_DOUBLE_EQ(rt.hli.spindle_control[0].override_percent, 50);
  EXPECT_TRUE(rt.hli.spindle_control[0].override_valid);
  EXPECT_DOUBLE_EQ(rt.hli.spindle_control[0].effective_override_percent(), 50);
  EXPECT_DOUBLE_EQ(rt.hli.channel[1].feed_override_percent, 80);
  EXPECT_DOUBLE_EQ(rt.hli.channel[0].feed_override_percent, 100);
  EXPECT_TRUE(rt.hli.channel[0].feedhold);
  EXPECT_TRUE(rt.hli.spindle_control[1].feedhold);
  EXPECT_FALSE(rt.hli.spindle_control[0].feedhold);
  EXPECT_TRUE(rt.hli.spindle_control[2].stop_at_program_end);   // S3, channel 2
  EXPECT_FALSE(rt.hli.spindle_control[0].stop_at_program_end);
  EXPECT_TRUE(rt.hli.spindle_control[0].reset);
  EXPECT_TRUE(rt.hli.channel[0].optional_stop);
  EXPECT_TRUE(rt.hli.channel[0].reset);
  EXPECT_FALSE(rt.hli.channel[1].reset);
  EXPECT_FALSE(rt.hli.spindle_control[1].override_valid);
}

TEST(ScenarioApply, SilentSwitchesThePlc) {
  Fixture f("0 silent on\n");
  Runtime rt;
  apply_all(f, rt);
  EXPECT_TRUE(rt.plc.silent());
  TechOutput o;
  o.number = 100;
  auto h = rt.plc.submit(o, 0.0);
  rt.plc.tick(10.0);
  EXPECT_FALSE(rt.plc.acknowledged(h));
}

TEST(ScenarioApply, ExternalCommandsQueueInFileOrder) {
  Fixture f("1 spindle_cmd S2 M3 REV500\n1 spindle_cmd S1 M19 POS90 REV100\n1 spindle_cmd S2 M5\n");
  ASSERT_TRUE(f.diags.empty());
  Runtime rt;
  apply_all(f, rt);
  ExtSpindleCommand c;
  ASSERT_TRUE(rt.ext.pop(c));
  EXPECT_EQ(c.seq, 1u);
  EXPECT_EQ(c.spindle, 1);
  EXPECT_EQ(c.fn, ExtFunction::m3);
  ASSERT_TRUE(rt.ext.pop(c));
  EXPECT_EQ(c.spindle, 0);
  EXPECT_EQ(c.fn, ExtFunction::m19);
  EXPECT_DOUBLE_EQ(c.pos_deg, 90);
  ASSERT_TRUE(rt.ext.pop(c));
  EXPECT_EQ(c.fn, ExtFunction::m5);
  EXPECT_EQ(c.seq, 3u);
}

TEST(ScenarioApply, FullQueueAndUnresolvedAreReported) {
  Runtime rt;
  Diagnostics d;
  auto sc = parse_scenario("0 spindle_cmd S1 M3 REV1\n0 override S1 50\n", "u.plc", d);
  SpindleMap map;  // not resolved: no spindle
  EXPECT_EQ(apply(sc.actions[0], map, rt.hli, rt.plc, rt.ext), ApplyResult::no_spindle);
  EXPECT_EQ(apply(sc.actions[1], map, rt.hli, rt.plc, rt.ext), ApplyResult::no_spindle);
  Fixture f("0 spindle_cmd S1 M3 REV1\n");
  for (std::size_t i = 0; i < ExtCommandQueue::kCapacity; ++i)
    EXPECT_EQ(apply(f.sc.actions[0], f.map, rt.hli, rt.plc, rt.ext), ApplyResult::ok);
  EXPECT_EQ(apply(f.sc.actions[0], f.map, rt.hli, rt.plc, rt.ext), ApplyResult::ext_queue_full);
}

}  // namespace
}  // namespace nck::plc
