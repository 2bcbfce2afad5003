#include <gtest/gtest.h>

#include "scenario_parse_helpers.hpp"

#include "scenario_fixture.hpp"

namespace nck::sim {
namespace {

using testing::Fixture;

TEST(ScenarioResolve, NamesBecomeIndices) {
  Fixture f("0 override S2 50\n0 ch=2 override S3 60\n0 override S 70\n0 spindle_cmd s1 M3 REV10\n");
  EXPECT_TRUE(f.diags.empty());
  ASSERT_EQ(f.sc.actions.size(), 4u);
  using testing::spindle_of;
  EXPECT_EQ(spindle_of(f.sc.actions[0]).index, 1);
  EXPECT_EQ(spindle_of(f.sc.actions[0]).hli, 1);
  EXPECT_EQ(spindle_of(f.sc.actions[1]).index, 0);
  EXPECT_EQ(spindle_of(f.sc.actions[1]).hli, 2);
  EXPECT_EQ(spindle_of(f.sc.actions[2]).index, 1);  // main spindle of channel 1 = S2
  EXPECT_EQ(testing::cmd_of(f.sc.actions[3]).spindle, 0);
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
  EXPECT_EQ(f.sc.actions[0].kind(), ActionKind::reset);
}

}  // namespace
}  // namespace nck::sim
