// '#' commands decoded into typed structs, with argument checks.
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

TEST(NcHash, Couplings) {
  auto d = decode("N10 #SET AX LINK[1, S2=S, S3=S]\nN20 #ENABLE AX LINK[1]\n#DISABLE AX LINK\n"
                  "#AX LINK[2, S2=S]\n#AX LINK ON[2]\n#AX LINK OFF\n#AX LINK NBR[1, 11=6, 17=6]\n"
                  "#AX LINK OFF ALL\n#SET AX LINK[3, [X2=X, G, 0.01, 0.25]]\n#AX LINK OFF[P1]\nM30\n");
  EXPECT_TRUE(d.has(ErrorId::NcUndefinedVariable)) << dump(d);  // P1 unset in the last one
  const auto& s = cmd<SetAxLink>(d, 0);
  EXPECT_EQ(s.group, 1);
  ASSERT_EQ(s.pairs.size(), 2u);
  EXPECT_EQ(s.pairs[1].slave, "S3");
  EXPECT_EQ(s.pairs[1].master, "S");
  EXPECT_EQ(cmd<EnableAxLink>(d, 1).group, 1);
  EXPECT_FALSE(cmd<DisableAxLink>(d, 2).group.has_value());
  EXPECT_EQ(cmd<EnableAxLink>(d, 4).group, 2);
  const auto& n = cmd<SetAxLink>(d, 6);
  EXPECT_TRUE(n.by_number);
  EXPECT_EQ(n.pairs[0].slave, "11");
  EXPECT_TRUE(cmd<DisableAxLink>(d, 7).all);
  const auto& g = cmd<SetAxLink>(d, 8);
  EXPECT_TRUE(g.pairs[0].gantry);
  EXPECT_DOUBLE_EQ(*g.pairs[0].limit2_mm, 0.25);
  EXPECT_EQ(hash_command_name(*d.blocks[0].hash), "#SET AX LINK");
  EXPECT_TRUE(decode("#SET AX LINK[0, S2=S]\n").has(ErrorId::NcHashArguments));
  EXPECT_TRUE(decode("#SET AX LINK[1]\n").has(ErrorId::NcHashArguments));
  EXPECT_TRUE(decode("#SET AX LINK[1, S9=S]\n").has(ErrorId::NcHashArguments));
}

TEST(NcHash, SpindleAndKinematics) {
  auto d = decode("#CAX [S, C]\n#FACE [X, C]\n#FACE OFF\n#CYL [Z, C, X60]\n#CYL OFF\n#CAX OFF\n#EXPL SYN\n"
                  "#TOOL DATA [P10, 2, ]\n#TOOL PREP [5]\nM30\n");
  // P10 is unset: the #TOOL DATA block fails.
  EXPECT_TRUE(d.has(ErrorId::NcUndefinedVariable));
  EXPECT_EQ(cmd<CAxis>(d, 0).axis, "C");
  EXPECT_EQ(cmd<Face>(d, 1).axis2, "C");
  EXPECT_FALSE(cmd<Face>(d, 2).on);
  EXPECT_DOUBLE_EQ(cmd<Cylinder>(d, 3).radius_mm, 60);
  EXPECT_EQ(cmd<Cylinder>(d, 3).axis3, "X");
  EXPECT_FALSE(cmd<CAxis>(d, 5).on);
  cmd<ExplSyn>(d, 6);
  auto t = decode("P10 = 7\n#TOOL DATA [P10, 2, ]\n#TOOL PREP [5]\nM30\n");
  const auto& td = cmd<ToolData>(t, 0);
  EXPECT_EQ(td.count, 3);
  EXPECT_EQ(td.fields[0], 7);
  EXPECT_EQ(td.fields[1], 2);
  EXPECT_EQ(td.fields[2], 0);
  EXPECT_TRUE(cmd<ToolData>(t, 1).prep);
  EXPECT_TRUE(decode("#CAX [S2, C]\n").has(ErrorId::NcCaxNotMainSpindle));
}

TEST(NcHash, CoordinateSystems) {
  auto d = decode("N10 #CS ON [1][0,0,10,0,0,45]\n#CS DEF [2][,,5]\n#CS ON [2]\n#CS ON\n#CS OFF\n#CS OFF ALL\n"
                  "#CS ADD [WCS][15,20,0,0,0,0]\n#CS SELECT [MCS]\n#CS MODE ON [ROTATION_SEQUENCE=ZYX]\n"
                  "#ACS ON [2][0,0,0,0,0,1.5]\n#ACS OFF\n#ECS ON\n#ECS OFF\n#MCS ON [EX TOOL]\n#MCS OFF\n"
                  "#CS ON [0,0,10]\nM30\n");
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  const auto& c0 = cmd<CoordSystem>(d, 0);
  EXPECT_EQ(c0.op, CsOp::on);
  EXPECT_EQ(c0.id, 1);
  EXPECT_DOUBLE_EQ(c0.values[2], 10);
  EXPECT_DOUBLE_EQ(c0.values[5], 45);
  const auto& c1 = cmd<CoordSystem>(d, 1);
  EXPECT_EQ(c1.op, CsOp::def);
  EXPECT_DOUBLE_EQ(c1.values[2], 5);
  EXPECT_FALSE(cmd<CoordSystem>(d, 2).has_values);
  EXPECT_EQ(cmd<CoordSystem>(d, 2).id, 2);
  EXPECT_FALSE(cmd<CoordSystem>(d, 3).id.has_value());
  EXPECT_EQ(cmd<CoordSystem>(d, 4).op, CsOp::off);
  EXPECT_EQ(cmd<CoordSystem>(d, 5).op, CsOp::off_all);
  EXPECT_EQ(cmd<CoordSystem>(d, 6).name, "WCS");
  EXPECT_DOUBLE_EQ(cmd<CoordSystem>(d, 6).values[1], 20);
  EXPECT_EQ(cmd<CoordSystem>(d, 7).op, CsOp::select);
  EXPECT_EQ(cmd<CoordSystem>(d, 8).mode_option, "ROTATION_SEQUENCE=ZYX");
  EXPECT_TRUE(cmd<CoordSystem>(d, 9).acs);
  EXPECT_DOUBLE_EQ(cmd<CoordSystem>(d, 9).values[5], 1.5);
  EXPECT_TRUE(cmd<Ecs>(d, 11).on);
  EXPECT_TRUE(cmd<Mcs>(d, 13).ex_tool);
  EXPECT_FALSE(cmd<Mcs>(d, 14).on);
  EXPECT_DOUBLE_EQ(cmd<CoordSystem>(d, 15).values[2], 10);
  EXPECT_FALSE(cmd<CoordSystem>(d, 15).id.has_value());
  EXPECT_TRUE(decode("#CS ON [6]\n").has(ErrorId::NcHashArguments));
  EXPECT_TRUE(decode("#CS DEF\n").has(ErrorId::NcHashArguments));
  EXPECT_TRUE(decode("#CS ON [1][1,2,3,4,5,6,7]\n").has(ErrorId::NcHashArguments));
  EXPECT_TRUE(decode("#CS ADD [MCS][1]\n").has(ErrorId::NcHashArguments));
  EXPECT_TRUE(decode("#ECS DEF\n").has(ErrorId::NcEcsDef));
}

TEST(NcHash, OffsetsAndRotation) {
  auto d = decode("#ROTATION ON [ANGLE=30 CENTER1=10 CENTER2=5]\n#ROTATION OFF\nN20 #PSET X20 Y20\n"
                  "N40 #PRESET X10\n#PRESET\n#TLC ON [15]\n#TLC OFF\n#SUPPRESS OFFSETS [ZERO TOOL] X0\n"
                  "#SUPPRESS OFFSETS X50 Y100\n#GET MANUAL OFFSETS\nM30\n");
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  const auto& r = cmd<Rotation>(d, 0);
  EXPECT_DOUBLE_EQ(*r.angle_deg, 30);
  EXPECT_DOUBLE_EQ(*r.center2_mm, 5);
  const auto& ps = cmd<PSet>(d, 2);
  ASSERT_EQ(ps.axes.size(), 2u);
  EXPECT_EQ(ps.axes[1], (std::pair<int, double>{1, 20.0}));
  EXPECT_FALSE(d.blocks[2].has_axis_words());
  EXPECT_EQ(cmd<PReset>(d, 3).axes, std::vector<int>{0});
  EXPECT_TRUE(cmd<PReset>(d, 4).axes.empty());
  EXPECT_DOUBLE_EQ(cmd<Tlc>(d, 5).delta_mm, 15);
  const auto& so = cmd<SuppressOffsets>(d, 7);
  EXPECT_TRUE(so.zero && so.tool && !so.all && !so.pset);
  EXPECT_DOUBLE_EQ(*d.blocks[7].axes[0], 0);  // the axes still move
  EXPECT_TRUE(cmd<SuppressOffsets>(d, 8).all);
  cmd<GetManualOffsets>(d, 9);
  EXPECT_TRUE(decode("#PSET G1 X20\n").has(ErrorId::NcPsetWithPathCondition));
  EXPECT_TRUE(decode("#PSET\n").has(ErrorId::NcHashArguments));
  EXPECT_TRUE(decode("#ROTATION ON [FOO=1]\n").has(ErrorId::NcHashArguments));
}

TEST(NcHash, ExclusivityAndUnknown) {
  EXPECT_TRUE(decode("X1 #CS OFF\n").has(ErrorId::NcHashNotAlone));
  EXPECT_TRUE(decode("#CS OFF X1\n").has(ErrorId::NcHashNotAlone));
  EXPECT_TRUE(decode("#FOO BAR\n").has(ErrorId::NcUnknownHashCommand));
  auto ok = decode("N5 #EXPL SYN\nM30\n");
  EXPECT_EQ(ok.errors(), 0u);
  EXPECT_EQ(ok.blocks[0].n, 5);
  auto msg = decode("#MSG [\"hello\"]\nM30\n");
  EXPECT_TRUE(msg.has(ErrorId::NcIgnoredCommand));
  EXPECT_EQ(msg.errors(), 0u);
}

}  // namespace
}  // namespace nck::nc::test
