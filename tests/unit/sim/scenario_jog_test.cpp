// Manual mode lines of the --plc scenario (issue 27): jog, jog_increment,
// mode; bad lines get their ID, file and line.
#include <string>

#include <gtest/gtest.h>

#include "nck/sim/scenario.hpp"
#include "scenario_parse_helpers.hpp"

namespace nck::sim {
namespace {

using namespace testing;

TEST(ScenarioJog, ContinuousJogStartAndStop) {
  auto a = one("1.5 jog X + 600");
  EXPECT_EQ(a.kind(), ActionKind::jog);
  auto j = payload<act::Jog>(a);
  EXPECT_EQ(j.axis.view(), "X");
  EXPECT_EQ(j.direction, 1);
  EXPECT_DOUBLE_EQ(j.speed_mm_min, 600.0);
  j = payload<act::Jog>(one("2 JOG y -"));
  EXPECT_EQ(j.direction, -1);
  EXPECT_DOUBLE_EQ(j.speed_mm_min, 0.0);  // the axis's P-AXIS-00077
  EXPECT_EQ(payload<act::Jog>(one("3 jog X stop   # released")).direction, 0);
  EXPECT_EQ(action_name(ActionKind::jog), "jog");
}

TEST(ScenarioJog, IncrementAndMode) {
  auto a = one("0 ch=1 jog_increment Z - 0.25");
  EXPECT_EQ(a.kind(), ActionKind::jog_increment);
  EXPECT_EQ(payload<act::JogIncrement>(a).direction, -1);
  EXPECT_DOUBLE_EQ(payload<act::JogIncrement>(a).step_mm, 0.25);
  a = one("0 mode manual");
  EXPECT_EQ(a.kind(), ActionKind::mode);
  EXPECT_TRUE(payload<act::Mode>(a).manual);
  EXPECT_FALSE(payload<act::Mode>(one("4 mode Automatic")).manual);
}

TEST(ScenarioJog, BadLinesHaveIdFileAndLine) {
  for (const char* text : {"0 jog X up", "0 jog X + 0", "0 jog X + -5", "0 jog X + fast", "0 jog_increment X stop 1",
                           "0 jog_increment X + 0", "0 jog_increment X + -1", "0 jog_increment X * 1"}) {
    const Diagnostic d = bad(text);
    EXPECT_EQ(d.id, ErrorId::PlcScenarioBadJog) << text;
    EXPECT_EQ(d.loc.file, "s.plc") << text;
    EXPECT_EQ(d.loc.line, 1u) << text;
  }
  EXPECT_EQ(bad("0 jog").id, ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(bad("0 jog X").id, ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(bad("0 jog_increment X +").id, ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(bad("0 jog X stop 600").id, ErrorId::PlcScenarioExtraArgument);
  EXPECT_EQ(bad("0 jog X + 600 more").id, ErrorId::PlcScenarioExtraArgument);
  EXPECT_EQ(bad("0 jog 5 +").id, ErrorId::PlcScenarioBadNumber);  // not an axis name
  EXPECT_EQ(bad("0 mode auto").id, ErrorId::PlcScenarioBadMode);
  EXPECT_EQ(bad("0 mode").id, ErrorId::PlcScenarioMissingArgument);
  // the line number of a bad line among good ones
  auto p = parse("0 mode manual\n\n1 jog X sideways\n2 jog X stop\n");
  ASSERT_EQ(p.diags.items().size(), 1u);
  EXPECT_EQ(p.diags.items()[0].loc.line, 3u);
  EXPECT_EQ(p.sc.actions.size(), 2u);
}

}  // namespace
}  // namespace nck::sim
