// Spindle words: DIN syntax of the main spindle and S..[ ] (docs/nc-language.md, "Spindles").
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

const SpindleCommand& only(const Block& b) {
  EXPECT_EQ(b.spindles.size(), 1u);
  return b.spindles.at(0);
}

TEST(NcSpindle, DinWordsOfTheSeedExample) {
  auto d = decode("N10 M03 S1000\nN20 Z0\nN30 M04 S1000\nN50 M05\nN60 M19 S200 S.POS100\nN70 M19 S.POS=180 M3 S100\n"
                  "N80 S.POS 90\nN90 S.POS_SHIFT=5\nM30\n");
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  const auto& s0 = only(d.blocks[0]);
  EXPECT_EQ(s0.name, "S");
  EXPECT_EQ(s0.target, "S1");
  EXPECT_TRUE(s0.din);
  EXPECT_EQ(s0.m, SpindleM::m3);
  EXPECT_DOUBLE_EQ(*s0.rev_rpm, 1000);
  EXPECT_TRUE(d.blocks[0].m.empty());  // spindle M functions live in the spindle command
  EXPECT_TRUE(d.blocks[1].spindles.empty());
  EXPECT_EQ(only(d.blocks[2]).m, SpindleM::m4);
  EXPECT_EQ(only(d.blocks[3]).m, SpindleM::m5);
  const auto& s4 = only(d.blocks[4]);
  EXPECT_EQ(s4.m, SpindleM::m19);
  EXPECT_DOUBLE_EQ(*s4.pos_deg, 100);
  EXPECT_DOUBLE_EQ(*s4.rev_rpm, 200);
  const auto& s5 = only(d.blocks[5]);
  EXPECT_EQ(s5.m, SpindleM::m19);
  EXPECT_EQ(s5.direction, SpindleM::m3);
  EXPECT_DOUBLE_EQ(*s5.pos_deg, 180);
  EXPECT_DOUBLE_EQ(*only(d.blocks[6]).pos_deg, 90);
  EXPECT_DOUBLE_EQ(*only(d.blocks[7]).pos_shift_deg, 5);
}

TEST(NcSpindle, SpecialSWords) {
  auto d = decode("G74 S1\nG167 S1000\nM41 S800 M3\nG112 S2\nS=500\nG130 S50\nM30\n");
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  EXPECT_TRUE(only(d.blocks[0]).g74);
  EXPECT_FALSE(only(d.blocks[0]).rev_rpm.has_value());
  EXPECT_TRUE(only(d.blocks[1]).g167);
  EXPECT_DOUBLE_EQ(*only(d.blocks[1]).rev_rpm, 1000);
  EXPECT_EQ(only(d.blocks[2]).gear_stage, 2);
  EXPECT_EQ(only(d.blocks[3]).g112_stage, 2);
  EXPECT_DOUBLE_EQ(*only(d.blocks[4]).rev_rpm, 500);
  EXPECT_DOUBLE_EQ(*only(d.blocks[5]).g130_pct, 50);
  for (int m = 40; m <= 45; ++m)
    EXPECT_EQ(only(decode("M" + std::to_string(m) + "\nM30\n").blocks.at(0)).gear_stage, m - 39);
}

TEST(NcSpindle, SpindleSyntaxAllKeywords) {
  auto d = decode(
      "N10 S[M3 REV500] S2[M4 REV=5000 G135 G136=90]\n"
      "N20 S[M19 REV200 POS90]\nN30 S2[G167 REV1000]\nS3[G74]\nS[G137]\nS2[G130=80]\n"
      "S3[DEFAULT_DYNAMIC_DATA]\nS3[DEFAUL_DYNAMIK_DATA]\nS2[GET_DYNAMIC_DATA]\nS2[GET_DYNAMIK_DATA]\n"
      "S2[CALLAX]\nS2[PUTAX]\nS2[M=8 H=3 M=9 \\\n REV 100 M5]\nS2[OVERRIDE SPEED_FACT=50]\n"
      "S2[FEED_LINK ON FACT=500 CORR=2 MAIN SRC=X]\nM30\n");
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  ASSERT_EQ(d.blocks[0].spindles.size(), 2u);
  EXPECT_EQ(d.blocks[0].spindles[0].target, "S1");
  EXPECT_FALSE(d.blocks[0].spindles[0].din);
  EXPECT_DOUBLE_EQ(*d.blocks[0].spindles[0].rev_rpm, 500);
  const auto& s2 = d.blocks[0].spindles[1];
  EXPECT_EQ(s2.name, "S2");
  EXPECT_EQ(s2.m, SpindleM::m4);
  EXPECT_DOUBLE_EQ(*s2.rev_rpm, 5000);
  EXPECT_TRUE(s2.g135);
  EXPECT_DOUBLE_EQ(*s2.g136_pct, 90);
  EXPECT_EQ(only(d.blocks[1]).m, SpindleM::m19);
  EXPECT_DOUBLE_EQ(*only(d.blocks[1]).pos_deg, 90);
  EXPECT_TRUE(only(d.blocks[2]).g167);
  EXPECT_TRUE(only(d.blocks[3]).g74);
  EXPECT_TRUE(only(d.blocks[4]).g137);
  EXPECT_DOUBLE_EQ(*only(d.blocks[5]).g130_pct, 80);
  EXPECT_TRUE(only(d.blocks[6]).default_dynamic_data);
  EXPECT_TRUE(only(d.blocks[7]).default_dynamic_data);
  EXPECT_TRUE(only(d.blocks[8]).get_dynamic_data);
  EXPECT_TRUE(only(d.blocks[9]).get_dynamic_data);
  EXPECT_TRUE(only(d.blocks[10]).callax);
  EXPECT_TRUE(only(d.blocks[11]).putax);
  const auto& um = only(d.blocks[12]);
  EXPECT_EQ(um.user_m, (std::vector<int>{8, 9}));
  EXPECT_EQ(um.user_h, std::vector<int>{3});
  EXPECT_EQ(um.m, SpindleM::m5);
  EXPECT_DOUBLE_EQ(*um.rev_rpm, 100);
  EXPECT_EQ(d.blocks[12].line, 13u);
  EXPECT_DOUBLE_EQ(*only(d.blocks[13]).override_speed_fact_pct, 50);
  const auto& fl = *only(d.blocks[14]).feed_link;
  EXPECT_EQ(fl.on, true);
  EXPECT_DOUBLE_EQ(*fl.fact_pct, 50);
  EXPECT_DOUBLE_EQ(*fl.corr, 2);
  EXPECT_TRUE(fl.main);
  EXPECT_EQ(fl.src, "X");
}

TEST(NcSpindle, DinForAnotherSpindleIs21044) {
  auto d = decode("S2=1000 M3\n");
  ASSERT_TRUE(d.has(ErrorId::NcDinForNonMainSpindle)) << dump(d);
  EXPECT_EQ(number(ErrorId::NcDinForNonMainSpindle), 21044u);
  EXPECT_EQ(d.find(ErrorId::NcDinForNonMainSpindle)->loc.column, 1u);
  EXPECT_TRUE(decode("S2.POS=10\n").has(ErrorId::NcDinForNonMainSpindle));
}

TEST(NcSpindle, NameErrors) {
  EXPECT_TRUE(decode("S7[M3]\n").has(ErrorId::NcUnknownSpindle));
  EXPECT_TRUE(decode("S1[M3 REV100]\n").has(ErrorId::NcMainSpindleByOwnName));
  EXPECT_TRUE(decode("S2[M3] S2[M4]\n").has(ErrorId::NcSpindleTwice));
  EXPECT_TRUE(decode("M3 S100 S[REV200]\n").has(ErrorId::NcSpindleTwice));
  EXPECT_TRUE(decode("S2[FOO]\n").has(ErrorId::NcSpindleKeyword));
  EXPECT_TRUE(decode("S2[M3 REV100\n").has(ErrorId::NcExprSyntax));
  EXPECT_TRUE(decode("S2[G167/]\n").has(ErrorId::NcSpindleKeyword));
}

TEST(NcSpindle, MainSpindleSwitch) {
  auto d = decode("#MAIN SPINDLE [S2]\nS110 M3 S1[REV210 M3]\n#MAIN SPINDLE [6]\n#MAIN SPINDLE\nS1[M3]\nM30\n");
  EXPECT_TRUE(d.has(ErrorId::NcMainSpindleByOwnName)) << dump(d);  // S1 is main again in the last block
  ASSERT_GE(d.blocks.size(), 4u);
  const auto& ms = std::get<MainSpindle>(*d.blocks[0].hash);
  EXPECT_EQ(*ms.name, "S2");
  ASSERT_EQ(d.blocks[1].spindles.size(), 2u);
  EXPECT_EQ(d.blocks[1].spindles[0].target, "S2");
  EXPECT_EQ(d.blocks[1].spindles[1].target, "S1");
  EXPECT_EQ(*std::get<MainSpindle>(*d.blocks[2].hash).log_axis_nr, 6);
  EXPECT_EQ(*std::get<MainSpindle>(*d.blocks[2].hash).name, "S1");
  EXPECT_FALSE(std::get<MainSpindle>(*d.blocks[3].hash).name.has_value());
  EXPECT_TRUE(decode("#MAIN SPINDLE [S9]\n").has(ErrorId::NcUnknownSpindle));
}

TEST(NcSpindle, CombinationErrors) {
  EXPECT_TRUE(decode("M3 M4\n").has(ErrorId::NcSpindleMConflict));
  EXPECT_TRUE(decode("M3 M5 S100\n").has(ErrorId::NcSpindleMConflict));
  EXPECT_TRUE(decode("S2[M3 M4]\n").has(ErrorId::NcSpindleMConflict));
  EXPECT_TRUE(decode("M19 M5\n").has(ErrorId::NcM19WithM5));
  EXPECT_TRUE(decode("S2[M19 M5 POS10]\n").has(ErrorId::NcM19WithM5));
  EXPECT_TRUE(decode("G74 S1 M3\n").has(ErrorId::NcG74WithSpindleM));
  EXPECT_TRUE(decode("S2[G74 M3]\n").has(ErrorId::NcG74WithSpindleM));
  EXPECT_TRUE(decode("G74 X1 M41\n").has(ErrorId::NcGearChangeWithG74));
  EXPECT_TRUE(decode("M41 M42\n").has(ErrorId::NcGearStageConflict));
  EXPECT_TRUE(decode("S2[G136=50 G136=60]\n").has(ErrorId::NcSpindleG136Twice));
  EXPECT_TRUE(decode("S2[G136=50 G130=60]\n").has(ErrorId::NcSpindleG136WithG130));
  EXPECT_TRUE(decode("S2[GET_DYNAMIC_DATA M3]\n").has(ErrorId::NcSpindleCombination));
  EXPECT_TRUE(decode("S2[G135 G74]\n").has(ErrorId::NcSpindleCombination));
  EXPECT_TRUE(decode("S2[OVERRIDE SPEED_FACT=300]\n").has(ErrorId::NcOverrideRange));
  EXPECT_TRUE(decode("S2[REV-5]\n").has(ErrorId::NcNegativeSpeed));
  EXPECT_TRUE(decode("S2[M3 M19 POS5]\nM30\n").diags.empty());  // direction for M19
}

}  // namespace
}  // namespace nck::nc::test
