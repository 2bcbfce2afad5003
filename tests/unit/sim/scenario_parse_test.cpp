#include <string>

#include <gtest/gtest.h>

#include "nck/sim/scenario.hpp"
#include "nck/sim/scenario_player.hpp"
#include "scenario_parse_helpers.hpp"

namespace nck::sim {
namespace {

using namespace testing;

TEST(ScenarioParse, SpecExamples) {
  auto a = one("0.5 override S1 50");
  EXPECT_EQ(a.kind(), ActionKind::spindle_override);
  EXPECT_DOUBLE_EQ(a.t_s, 0.5);
  EXPECT_EQ(spindle_of(a).view(), "S1");
  EXPECT_DOUBLE_EQ(percent_of(a), 50);
  EXPECT_EQ(a.channel, 1);
  EXPECT_EQ(a.line, 1u);

  a = one("1.0 feed_override 80");
  EXPECT_EQ(a.kind(), ActionKind::feed_override);
  EXPECT_DOUBLE_EQ(percent_of(a), 80);
  EXPECT_FALSE(spindle_of(a).given());

  a = one("1.1 rapid_override 25");
  EXPECT_EQ(a.kind(), ActionKind::rapid_override);
  EXPECT_DOUBLE_EQ(percent_of(a), 25);

  a = one("1.2 feedhold on");
  EXPECT_EQ(a.kind(), ActionKind::feedhold);
  EXPECT_TRUE(on_of(a));

  a = one("2.0 spindle_stop_at_end on");
  EXPECT_EQ(a.kind(), ActionKind::spindle_stop_at_end);
  EXPECT_TRUE(on_of(a));
  EXPECT_FALSE(spindle_of(a).given());

  a = one("2.5 reset");
  EXPECT_EQ(a.kind(), ActionKind::reset);
  EXPECT_DOUBLE_EQ(a.t_s, 2.5);

  a = one("3.0 spindle_cmd S2 M3 REV500");
  EXPECT_EQ(a.kind(), ActionKind::spindle_cmd);
  EXPECT_EQ(spindle_of(a).view(), "S2");
  EXPECT_EQ(cmd_of(a).fn, plc::ExtFunction::m3);
  EXPECT_TRUE(cmd_of(a).has_rev);
  EXPECT_DOUBLE_EQ(cmd_of(a).rev_rpm, 500);
  EXPECT_FALSE(cmd_of(a).has_pos);
  EXPECT_EQ(std::string_view(cmd_of(a).spindle_name.data()), "S2");
}

TEST(ScenarioParse, EveryOtherAction) {
  auto a = one("0 spindle_override S3 120.5");
  EXPECT_EQ(a.kind(), ActionKind::spindle_override);
  EXPECT_DOUBLE_EQ(percent_of(a), 120.5);
  a = one("0 override_valid S1 off");
  EXPECT_EQ(a.kind(), ActionKind::override_valid);
  EXPECT_FALSE(on_of(a));
  a = one("0 feedhold off");
  EXPECT_FALSE(on_of(a));
  a = one("0 spindle_feedhold S1 1");
  EXPECT_EQ(a.kind(), ActionKind::spindle_feedhold);
  EXPECT_TRUE(on_of(a));
  a = one("0 spindle_stop_at_end off S2");
  EXPECT_EQ(spindle_of(a).view(), "S2");
  EXPECT_FALSE(on_of(a));
  a = one("0 spindle_reset S1");
  EXPECT_EQ(a.kind(), ActionKind::spindle_reset);
  a = one("0 optional_stop on");
  EXPECT_EQ(a.kind(), ActionKind::optional_stop);
  EXPECT_TRUE(on_of(a));
  a = one("4 silent on");
  EXPECT_EQ(a.kind(), ActionKind::silent);
  EXPECT_TRUE(on_of(a));
  a = one("5 silent 0");
  EXPECT_FALSE(on_of(a));
}

TEST(ScenarioParse, SpindleCommandForms) {
  auto a = one("1 spindle_cmd S1 M19 REV=200 POS=90.5");
  EXPECT_EQ(cmd_of(a).fn, plc::ExtFunction::m19);
  EXPECT_DOUBLE_EQ(cmd_of(a).rev_rpm, 200);
  EXPECT_TRUE(cmd_of(a).has_pos);
  EXPECT_DOUBLE_EQ(cmd_of(a).pos_deg, 90.5);
  a = one("1 spindle_cmd S1 POS 45 M19");  // any order, value as the next word
  EXPECT_DOUBLE_EQ(cmd_of(a).pos_deg, 45);
  EXPECT_FALSE(cmd_of(a).has_rev);
  a = one("1 spindle_cmd s1 m04 rev1500");
  EXPECT_EQ(cmd_of(a).fn, plc::ExtFunction::m4);
  EXPECT_DOUBLE_EQ(cmd_of(a).rev_rpm, 1500);
  a = one("1 spindle_cmd S1 M05");
  EXPECT_EQ(cmd_of(a).fn, plc::ExtFunction::m5);
  a = one("1 spindle_cmd S1 M19 POS-30");
  EXPECT_DOUBLE_EQ(cmd_of(a).pos_deg, -30);
}

TEST(ScenarioParse, ChannelPrefixes) {
  auto a = one("1 ch=2 feed_override 50");
  EXPECT_EQ(a.channel, 2);
  a = one("1 channel 3 spindle_cmd S1 M3 REV100");
  EXPECT_EQ(a.channel, 3);
  EXPECT_EQ(cmd_of(a).channel, 3);
  a = one("1 CH=12 reset");
  EXPECT_EQ(a.channel, 12);
}

TEST(ScenarioParse, CommentsBlankLinesAndCase) {
  auto p = parse(
      "# a PLC scenario\n"
      "\n"
      "   \t\r\n"
      "0.5 OVERRIDE S1 50   # half speed\r\n"
      "1e-1 Feed_Override +75\n");
  ASSERT_EQ(p.diags.items().size(), 1u);  // 0.1 s after 0.5 s
  EXPECT_EQ(p.diags.items()[0].id, ErrorId::PlcScenarioTimeBackwards);
  ASSERT_EQ(p.sc.actions.size(), 2u);
  EXPECT_EQ(p.sc.actions[0].kind(), ActionKind::feed_override);  // sorted: 0.1 s first
  EXPECT_EQ(p.sc.actions[0].line, 5u);
  EXPECT_DOUBLE_EQ(percent_of(p.sc.actions[0]), 75);
  EXPECT_EQ(p.sc.actions[1].line, 4u);
  EXPECT_EQ(p.sc.file, "s.plc");
}

TEST(ScenarioParse, TimeGoingBackwardsIsSortedWithAWarning) {
  auto p = parse("2 reset\n1 feedhold on\n1 feedhold off\n");
  ASSERT_EQ(p.diags.items().size(), 2u);  // lines 2 and 3 are both before 2 s
  EXPECT_EQ(p.diags.items()[0].id, ErrorId::PlcScenarioTimeBackwards);
  EXPECT_EQ(p.diags.items()[0].severity, Severity::warning);
  EXPECT_EQ(p.diags.items()[0].loc.line, 2u);
  EXPECT_FALSE(p.diags.has_errors());
  ASSERT_EQ(p.sc.actions.size(), 3u);
  // Stable: equal times keep the file order.
  EXPECT_EQ(p.sc.actions[0].line, 2u);
  EXPECT_TRUE(on_of(p.sc.actions[0]));
  EXPECT_EQ(p.sc.actions[1].line, 3u);
  EXPECT_EQ(p.sc.actions[2].kind(), ActionKind::reset);
}

TEST(ScenarioParse, BadTime) {
  auto d = bad("abc reset");
  EXPECT_EQ(d.id, ErrorId::PlcScenarioBadTime);
  EXPECT_EQ(d.loc.file, "s.plc");
  EXPECT_EQ(d.loc.line, 1u);
  EXPECT_EQ(d.loc.column, 1u);
  EXPECT_EQ(bad("-1 reset").id, ErrorId::PlcScenarioBadTime);
  EXPECT_EQ(bad("inf reset").id, ErrorId::PlcScenarioBadTime);
  EXPECT_EQ(bad("nan reset").id, ErrorId::PlcScenarioBadTime);
  EXPECT_EQ(bad("1.5s reset").id, ErrorId::PlcScenarioBadTime);
}

TEST(ScenarioParse, UnknownActionNamesTheNearest) {
  auto d = bad("1 feed_overide 80");
  EXPECT_EQ(d.id, ErrorId::PlcScenarioUnknownAction);
  EXPECT_EQ(d.loc.column, 3u);
  EXPECT_NE(d.message.find("feed_override"), std::string::npos) << d.message;
  EXPECT_EQ(bad("1").id, ErrorId::PlcScenarioMissingArgument);
}

TEST(ScenarioParse, BadNumbers) {
  auto d = bad("1 feed_override 250");
  EXPECT_EQ(d.id, ErrorId::PlcScenarioBadNumber);
  EXPECT_EQ(d.loc.column, 17u);
  EXPECT_EQ(bad("1 override S1 -5").id, ErrorId::PlcScenarioBadNumber);
  EXPECT_EQ(bad("1 override S1 fifty").id, ErrorId::PlcScenarioBadNumber);
  EXPECT_EQ(bad("1 spindle_cmd S1 M3 REV-10").id, ErrorId::PlcScenarioBadNumber);
  EXPECT_EQ(bad("1 spindle_cmd S1 M19 POSx").id, ErrorId::PlcScenarioBadNumber);
}

TEST(ScenarioParse, MissingAndExtraArguments) {
  auto d = bad("1 override S1");
  EXPECT_EQ(d.id, ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(d.loc.column, 14u);  // just after "S1"
  EXPECT_EQ(bad("1 feedhold").id, ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(bad("1 spindle_cmd").id, ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(bad("1 spindle_cmd S1 M3 REV").id, ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(bad("1 channel").id, ErrorId::PlcScenarioMissingArgument);
  d = bad("1 reset now");
  EXPECT_EQ(d.id, ErrorId::PlcScenarioExtraArgument);
  EXPECT_EQ(d.loc.column, 9u);
  EXPECT_EQ(bad("1 feed_override 80 90").id, ErrorId::PlcScenarioExtraArgument);
}

TEST(ScenarioParse, BadSpindleNamesSwitchesAndChannels) {
  auto d = bad("1 override X1 50");
  EXPECT_EQ(d.id, ErrorId::PlcScenarioBadSpindleName);
  EXPECT_EQ(d.loc.column, 12u);
  EXPECT_EQ(bad("1 override S-1 50").id, ErrorId::PlcScenarioBadSpindleName);
  EXPECT_EQ(bad("1 override S123456789012345 50").id, ErrorId::PlcScenarioBadSpindleName);
  d = bad("1 feedhold maybe");
  EXPECT_EQ(d.id, ErrorId::PlcScenarioBadSwitch);
  EXPECT_EQ(d.loc.column, 12u);
  EXPECT_EQ(bad("1 ch=0 reset").id, ErrorId::PlcScenarioBadChannel);
  EXPECT_EQ(bad("1 ch=13 reset").id, ErrorId::PlcScenarioBadChannel);
  EXPECT_EQ(bad("1 ch=1.5 reset").id, ErrorId::PlcScenarioBadChannel);
  EXPECT_EQ(bad("1 channel x reset").id, ErrorId::PlcScenarioBadChannel);
}

TEST(ScenarioParse, BadSpindleCommands) {
  EXPECT_EQ(bad("1 spindle_cmd S1 REV500").id, ErrorId::PlcScenarioBadSpindleCommand);
  EXPECT_EQ(bad("1 spindle_cmd S1 M3 M4").id, ErrorId::PlcScenarioBadSpindleCommand);
  EXPECT_EQ(bad("1 spindle_cmd S1 M5 REV100").id, ErrorId::PlcScenarioBadSpindleCommand);
  EXPECT_EQ(bad("1 spindle_cmd S1 M3 POS10").id, ErrorId::PlcScenarioBadSpindleCommand);
  EXPECT_EQ(bad("1 spindle_cmd S1 M6").id, ErrorId::PlcScenarioBadSpindleCommand);
  EXPECT_EQ(bad("1 spindle_cmd S1 M3 REV1 REV2").id, ErrorId::PlcScenarioBadSpindleCommand);
  auto d = bad("1 spindle_cmd S1 M3 G74");
  EXPECT_EQ(d.loc.column, 21u);
}

TEST(ScenarioParse, BadLinesAreSkippedOthersKept) {
  auto p = parse("0.1 feed_override 50\n0.2 bogus\n0.3 reset\n0.4 feedhold perhaps\n");
  ASSERT_EQ(p.diags.items().size(), 2u);
  EXPECT_EQ(p.diags.items()[0].loc.line, 2u);
  EXPECT_EQ(p.diags.items()[1].loc.line, 4u);
  EXPECT_EQ(p.sc.actions.size(), 2u);
  EXPECT_EQ(format(p.diags.items()[0]).rfind("s.plc:2:5: error 960002", 0), 0u)
      << format(p.diags.items()[0]);
}

TEST(ScenarioParse, TooManyActionsStops) {
  std::string text;
  for (std::size_t i = 0; i < kMaxScenarioActions + 5; ++i) text += "1 reset\n";
  auto p = parse(text);
  EXPECT_EQ(p.sc.actions.size(), kMaxScenarioActions);
  ASSERT_EQ(p.diags.items().size(), 1u);
  EXPECT_EQ(p.diags.items()[0].id, ErrorId::PlcScenarioTooLarge);
  EXPECT_EQ(p.diags.items()[0].loc.line, kMaxScenarioActions + 1);
}

TEST(ScenarioParse, ActionNames) {
  EXPECT_EQ(action_name(ActionKind::spindle_override), "override");
  EXPECT_EQ(action_name(ActionKind::spindle_cmd), "spindle_cmd");
}

// Issue 27: block search from the scenario, at time 0 only, once.
TEST(ScenarioParse, BlockSearch) {
  auto a = one("0 block_search N100 pass 2 covered 400 program sub.nc no_hold");
  EXPECT_EQ(a.kind(), ActionKind::block_search);
  const auto b = payload<act::BlockSearch>(a);
  EXPECT_EQ(b.mark_kind, prep::SearchMark::Kind::block_number);
  EXPECT_EQ(b.mark_value, 100);
  EXPECT_EQ(b.pass, 2u);
  EXPECT_DOUBLE_EQ(b.covered_permille, 400);
  EXPECT_STREQ(b.program.data(), "sub.nc");
  EXPECT_TRUE(b.no_hold_at_restart);
  EXPECT_EQ(payload<act::BlockSearch>(one("0 block_search block 17")).mark_kind, prep::SearchMark::Kind::block_counter);
  EXPECT_EQ(payload<act::BlockSearch>(one("0 block_search offset 0")).mark_kind, prep::SearchMark::Kind::file_offset);
  const auto p = parse("0 ch=2 block_search N5 covered 1000");
  const auto s = block_search_of(p.sc);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->channel, 1u);
  EXPECT_EQ(s->mark.value, 5);
  EXPECT_DOUBLE_EQ(s->mark.covered_permille, 1000);
  EXPECT_FALSE(s->mark.no_hold_at_restart);
  for (const char* text : {"0.5 block_search N100", "0 block_search", "0 block_search X", "0 block_search N1x",
                           "0 block_search block 0", "0 block_search offset -1", "0 block_search N1 covered 1001",
                           "0 block_search N1 pass 0", "0 block_search N1 pass", "0 block_search N1 fast"}) {
    const Diagnostic d = bad(text);
    EXPECT_TRUE(d.id == ErrorId::PlcScenarioBlockSearch || d.id == ErrorId::PlcScenarioMissingArgument) << text;
    EXPECT_EQ(d.loc.line, 1u) << text;
  }
  const auto twice = parse("0 block_search N1\n0 block_search N2\n");
  ASSERT_EQ(twice.diags.items().size(), 1u);
  EXPECT_EQ(twice.diags.items()[0].loc.line, 2u);
  EXPECT_EQ(block_search_of(twice.sc)->mark.value, 1);
}

// Issue 27: MDI text, the rest of the line up to a scenario comment.
TEST(ScenarioParse, MdiText) {
  const auto p = parse("0 mdi G1 X10  Y5 F1000   # comment\n1 ch=1 mdi G0 Z5\n");
  ASSERT_TRUE(p.diags.empty());
  ASSERT_EQ(p.sc.actions.size(), 2u);
  EXPECT_EQ(p.sc.actions[0].kind(), ActionKind::mdi);
  ASSERT_EQ(p.sc.texts.size(), 2u);
  EXPECT_EQ(p.sc.texts[payload<act::Mdi>(p.sc.actions[0]).text], "G1 X10  Y5 F1000");
  EXPECT_EQ(p.sc.texts[payload<act::Mdi>(p.sc.actions[1]).text], "G0 Z5");
  EXPECT_EQ(bad("0 mdi").id, ErrorId::PlcScenarioMissingArgument);
}

// Issue 27: lines that act when their channel first enters a program state.
TEST(ScenarioParse, TriggeredLines) {
  const auto p = parse("@hold cycle_start\n@ended+0.25 ch=1 feed_override 50\n1 reset\n");
  ASSERT_TRUE(p.diags.empty());
  ASSERT_EQ(p.sc.actions.size(), 1u);  // the timed one
  ASSERT_EQ(p.sc.triggered.size(), 2u);
  EXPECT_EQ(p.sc.triggered[0].trigger, kernel::ProgramState::hold);
  EXPECT_DOUBLE_EQ(p.sc.triggered[0].t_s, 0);
  EXPECT_EQ(p.sc.triggered[1].trigger, kernel::ProgramState::ended);
  EXPECT_DOUBLE_EQ(p.sc.triggered[1].t_s, 0.25);
  for (const char* text : {"@ cycle_start", "@holding cycle_start", "@hold+ cycle_start", "@hold+-1 cycle_start",
                           "@hold+x cycle_start"})
    EXPECT_EQ(bad(text).id, ErrorId::PlcScenarioBadTime) << text;
  EXPECT_EQ(bad("@idle block_search N1").id, ErrorId::PlcScenarioBlockSearch);
}

// A triggered line acts its delay after the state is first entered, once.
TEST(ScenarioPlayer, TriggeredLineActsOnceAfterItsState) {
  const auto p = parse("@hold+0.5 cycle_start\n");
  ScenarioPlayer player(p.sc);
  std::size_t given = 0;
  const auto count = [&](const ScenarioAction&) { ++given; };
  player.for_each_triggered_due(10.0, count);
  EXPECT_EQ(given, 0u);  // not armed
  EXPECT_TRUE(player.finished());
  player.entered(2, kernel::ProgramState::hold, 1.0);  // another channel
  player.entered(1, kernel::ProgramState::running, 1.0);
  EXPECT_TRUE(player.finished());
  player.entered(1, kernel::ProgramState::hold, 1.0);
  EXPECT_FALSE(player.finished());
  player.for_each_triggered_due(1.4, count);
  EXPECT_EQ(given, 0u);
  player.for_each_triggered_due(1.5, count);
  EXPECT_EQ(given, 1u);
  player.entered(1, kernel::ProgramState::hold, 2.0);  // once only
  player.for_each_triggered_due(9.0, count);
  EXPECT_EQ(given, 1u);
  EXPECT_TRUE(player.finished());
}

}  // namespace
}  // namespace nck::sim

namespace nck::sim {
namespace {

// variable <name> <value>: a channel variable (SENSOR_SOURCE=VARIABLE reads it).
TEST(ScenarioParse, ChannelVariable) {
  auto a = one("0.25 variable v.e.gap -1.5");
  EXPECT_EQ(a.kind(), ActionKind::variable);
  EXPECT_EQ(std::string(payload<act::Variable>(a).name.data()), "V.E.GAP");  // names are case-insensitive
  EXPECT_DOUBLE_EQ(payload<act::Variable>(a).value, -1.5);
  EXPECT_EQ(bad("0 variable V.E.GAP").id, ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(bad("0 variable V.E.GAP x").id, ErrorId::PlcScenarioBadNumber);
  EXPECT_EQ(bad("0 variable " + std::string(40, 'A') + " 1").id, ErrorId::PlcScenarioBadNumber);
}

// Issue 27: the operator's single step switch and the HLI skip levels.
TEST(ScenarioParse, SingleStepAndSkipMask) {
  auto a = one("0 single_step on");
  EXPECT_EQ(a.kind(), ActionKind::single_step);
  EXPECT_TRUE(on_of(a));
  a = one("1.5 skip_mask 0x5");
  EXPECT_EQ(a.kind(), ActionKind::skip_mask);
  EXPECT_EQ(payload<act::SkipMask>(a).mask, 5u);
  EXPECT_EQ(payload<act::SkipMask>(one("0 skip_mask 1023")).mask, 1023u);
  for (const char* text : {"0 skip_mask 1024", "0 skip_mask 0x400", "0 skip_mask -1", "0 skip_mask 0x", "0 skip_mask 1.5",
                           "0 skip_mask five"}) {
    const Diagnostic d = bad(text);
    EXPECT_EQ(d.id, ErrorId::PlcScenarioBadNumber) << text;
    EXPECT_EQ(d.loc.line, 1u) << text;
  }
  EXPECT_EQ(bad("0 skip_mask").id, ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(bad("0 single_step maybe").id, bad("0 feedhold maybe").id);
}

}  // namespace
}  // namespace nck::sim
