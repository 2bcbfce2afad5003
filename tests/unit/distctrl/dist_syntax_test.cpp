// #DIST CTRL in the decoder (src/distctrl/nc/dist_ctrl_syntax.cpp): the
// switch, its overrides and their checks, its name and its JSON form.
#include <nlohmann/json.hpp>

#include "../nc/nc_test_util.hpp"
#include "nck/nc/block_json.hpp"

namespace nck::nc::test {
namespace {

TEST(DistCtrlSyntax, SwitchesAndOverrides) {
  auto d = decode("#DIST CTRL ON [SURFACE SET_POS=100 KP=2 I_TN=0.5 D_TV=0.1 FILTER_TYPE=LOWPASS ORDER=2 FG_F0=50]\n"
                  "#DIST CTRL FREEZE\n#DIST CTRL ON [CONST_DIST SET_DIST=1.5 FILTER_TYPE=MOVING_AVERAGE N_CYCLES=8]\n"
                  "#DIST CTRL OFF\n#DIST CTRL ON [SMOOTH_FACT=0.5 FILTER_TYPE=EXPO_MEAN KALMAN_SIGMA=2]\nM30\n");
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  const auto& a = cmd<DistCtrl>(d, 0);
  EXPECT_EQ(a.op, DistCtrlOp::on);
  EXPECT_FALSE(a.const_dist);
  EXPECT_DOUBLE_EQ(*a.set_pos_mm, 100);
  EXPECT_DOUBLE_EQ(*a.kp, 2);
  EXPECT_EQ(*a.filter_type, "LOWPASS");
  EXPECT_EQ(*a.order, 2);
  EXPECT_EQ(cmd<DistCtrl>(d, 1).op, DistCtrlOp::freeze);
  const auto& c = cmd<DistCtrl>(d, 2);
  EXPECT_TRUE(c.const_dist);
  EXPECT_EQ(*c.n_cycles, 8);
  EXPECT_EQ(cmd<DistCtrl>(d, 3).op, DistCtrlOp::off);
  EXPECT_DOUBLE_EQ(*cmd<DistCtrl>(d, 4).smooth_fact, 0.5);  // SET_POS known from before
  EXPECT_EQ(number(ErrorId::NcDistCtrlNoSetPos), 310024u);
  EXPECT_TRUE(decode("#DIST CTRL ON\n").has(ErrorId::NcDistCtrlNoSetPos));
  EXPECT_TRUE(decode("#DIST CTRL ON [SET_POS=1]\n#DIST CTRL ON [CONST_DIST SET_DIST=1]\n")
                  .has(ErrorId::NcDistCtrlModeChange));
  EXPECT_TRUE(decode("#DIST CTRL ON [SET_POS=1 FILTER_TYPE=FOO]\n").has(ErrorId::NcHashArguments));
  EXPECT_TRUE(decode("#DIST CTRL ON [SET_POS=1 SMOOTH_FACT=3]\n").has(ErrorId::NcHashArguments));
  auto cfg = default_config();
  cfg.dist_ctrl_available = false;
  EXPECT_TRUE(decode("#DIST CTRL OFF\n", cfg).has(ErrorId::NcDistCtrlNotEnabled));
}

TEST(DistCtrlSyntax, NameAndJson) {
  auto d = decode("#DIST CTRL ON [CONST_DIST SET_DIST=1.5 KP=2]\n#DIST CTRL FREEZE\n#DIST CTRL OFF\n"
                  "#DIST CTRL [KP=3]\nM30\n");
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  EXPECT_EQ(hash_command_name(*d.blocks[0].hash), "#DIST CTRL ON");
  EXPECT_EQ(hash_command_name(*d.blocks[1].hash), "#DIST CTRL FREEZE");
  EXPECT_EQ(hash_command_name(*d.blocks[2].hash), "#DIST CTRL OFF");
  EXPECT_EQ(hash_command_name(*d.blocks[3].hash), "#DIST CTRL");
  nlohmann::json j;
  write_json(j, cmd<DistCtrl>(d, 0));
  EXPECT_EQ(j["mode"], "CONST_DIST");
  EXPECT_DOUBLE_EQ(j["set_dist_mm"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(j["kp"].get<double>(), 2);
  EXPECT_FALSE(j.contains("set_pos_mm"));
}

}  // namespace
}  // namespace nck::nc::test
