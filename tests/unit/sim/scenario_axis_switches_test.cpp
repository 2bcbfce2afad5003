// The --plc scenario's amplifier fault and limit switch lines (issue 46):
// amp_fault AXIS on|off, limit_switch AXIS +|- on|off; bad lines get an ID.
#include <gtest/gtest.h>

#include "nck/sim/scenario.hpp"
#include "scenario_parse_helpers.hpp"

namespace nck::sim {
namespace {

using namespace testing;

TEST(ScenarioAxisSwitches, AmpFaultAndLimitSwitchLines) {
  auto a = one("0.5 amp_fault Y on");
  EXPECT_EQ(a.kind(), ActionKind::amp_fault);
  EXPECT_EQ(payload<act::AmpFault>(a).axis.view(), "Y");
  EXPECT_TRUE(payload<act::AmpFault>(a).on);
  EXPECT_FALSE(payload<act::AmpFault>(one("1 AMP_FAULT y off")).on);
  a = one("0.5 limit_switch X - on");
  EXPECT_EQ(a.kind(), ActionKind::limit_switch);
  EXPECT_EQ(payload<act::LimitSwitch>(a).axis.view(), "X");
  EXPECT_EQ(payload<act::LimitSwitch>(a).direction, -1);
  EXPECT_TRUE(payload<act::LimitSwitch>(a).on);
  EXPECT_EQ(payload<act::LimitSwitch>(one("2 limit_switch Z + off")).direction, 1);
  EXPECT_EQ(action_name(ActionKind::limit_switch), "limit_switch");
  EXPECT_EQ(action_name(ActionKind::amp_fault), "amp_fault");
}

TEST(ScenarioAxisSwitches, BadLinesHaveAnId) {
  EXPECT_EQ(bad("0 amp_fault").id, ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(bad("0 amp_fault X").id, ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(bad("0 limit_switch X on").id, ErrorId::PlcScenarioBadJog);  // no direction
  EXPECT_EQ(bad("0 limit_switch X stop on").id, ErrorId::PlcScenarioBadJog);
  EXPECT_EQ(bad("0 limit_switch X +").id, ErrorId::PlcScenarioMissingArgument);
  EXPECT_EQ(bad("0 limit_switch X + on more").id, ErrorId::PlcScenarioExtraArgument);
}

}  // namespace
}  // namespace nck::sim
