// Seed FCT-S1 2.8.2: both programming examples, block by block, on the
// seed's range table (M40 50-560, M41 400-800, M42 700-3500, M43 3501-4000,
// M44 3800-5500, M45 5400-7000), range_way 0 (bottom up).
#include <gtest/gtest.h>

#include <cmath>

#include <optional>
#include <vector>

#include "nck/spindle/gear_select.hpp"

namespace nck::spindle {
namespace {

config::ChannelSpindle seed_spindle(bool autom) {
  config::ChannelSpindle sp;
  sp.name = "S1";
  sp.autom_range = autom;
  const double t[6][2] = {{50, 560}, {400, 800}, {700, 3500}, {3501, 4000}, {3800, 5500}, {5400, 7000}};
  for (int i = 0; i < 6; ++i) sp.range_table[i] = {t[i][0], t[i][1]};
  return sp;
}

struct Row {
  const char* block;
  std::optional<std::uint32_t> programmed;  // M40..M45 -> 1..6
  double s_rpm;
  std::optional<ErrorId> error;   // expected error, or
  std::uint32_t stage;            // expected stage after the block
  bool change;
};

void run(const config::ChannelSpindle& sp, const std::vector<Row>& rows) {
  std::uint32_t current = 1;  // kenngr.getriebe_stufe default
  for (const Row& r : rows) {
    SCOPED_TRACE(r.block);
    auto d = select_gear(sp, current, r.s_rpm, r.programmed);
    if (r.error) {
      ASSERT_FALSE(d.has_value());
      EXPECT_EQ(d.error(), *r.error);
      continue;  // the stage stays
    }
    ASSERT_TRUE(d.has_value()) << number(d.error());
    EXPECT_EQ(d->stage, r.stage);
    EXPECT_EQ(d->change, r.change);
    current = d->stage;
  }
}

TEST(GearSelect, AutomaticExample) {
  run(seed_spindle(true),
      {
          {"S650 M03", {}, 650, {}, 2, true},      // M41 -> PLC
          {"S750", {}, 750, {}, 2, false},         // M41 kept
          {"S950", {}, 950, {}, 3, true},          // M42 -> PLC
          {"S1050", {}, 1050, {}, 3, false},       // M42 kept
          // FCT-S1 §2.8.2 prints M41 here, against its own rule that a stage
          // covering S is kept: M42 covers 700..3500, so nck keeps M42
          // (docs/decisions.md, Spindles).
          {"S750", {}, 750, {}, 3, false},
          // Follows from keeping M42: it cannot run 500, the bottom-up
          // search takes M40 (50..560) (seed: "M41 kept", from its own chain).
          {"S500", {}, 500, {}, 1, true},
          {"S350", {}, 350, {}, 1, false},
          {"S8000", {}, 8000, ErrorId::SpindleSpeedTooHigh, 0, false},
          {"M41 S750", 2, 750, {}, 2, true},       // programmed stage is checked and taken
          {"M40 S750", 1, 750, ErrorId::SpindleGearStageWrong, 0, false},
      });
}

TEST(GearSelect, ManualExample) {
  run(seed_spindle(false),
      {
          {"M41 S650 M03", 2, 650, {}, 2, true},
          {"M41 S750", 2, 750, {}, 2, false},
          {"M42 S950", 3, 950, {}, 3, true},
          {"M42 S1050", 3, 1050, {}, 3, false},
          {"M41 S750", 2, 750, {}, 2, true},
          {"M41 S500", 2, 500, {}, 2, false},
          // Seed says OK, but M41 runs 400..800: by the seed's own rule (FCT-S1
          // §2.8.2: a manual stage must cover S) S350 is rejected like S200.
          {"M41 S350", 2, 350, ErrorId::SpindleGearStageWrong, 0, false},
          {"M41 S200", 2, 200, ErrorId::SpindleGearStageWrong, 0, false},
          {"S950", {}, 950, ErrorId::SpindleGearStageRequired, 0, false},
      });
}

TEST(GearSelect, TopDownSearchAndLimits) {
  auto sp = seed_spindle(true);
  sp.range_way = {6, 5, 4, 3, 2, 1};
  auto d = select_gear(sp, 1, 3900, std::nullopt);  // M43 and M44 cover it: top down takes M44
  ASSERT_TRUE(d);
  EXPECT_EQ(d->stage, 5u);
  d = select_gear(sp, 1, 500, std::nullopt);  // M40 covers it: kept
  ASSERT_TRUE(d);
  EXPECT_EQ(d->stage, 1u);
  EXPECT_FALSE(d->change);
  auto low = select_gear(sp, 4, 20, std::nullopt);
  ASSERT_FALSE(low);
  EXPECT_EQ(low.error(), ErrorId::SpindleSpeedTooLow);
  auto neg = select_gear(sp, 3, -900, std::nullopt);  // M4 S900: the magnitude counts
  ASSERT_TRUE(neg);
  EXPECT_EQ(neg->stage, 3u);
  auto zero = select_gear(sp, 4, 0, std::nullopt);
  ASSERT_TRUE(zero);
  EXPECT_EQ(zero->stage, 4u);
  sp.range_table[2] = {};  // unused stage
  auto gap = select_gear(sp, 1, 1000, std::nullopt);
  ASSERT_FALSE(gap);
  EXPECT_EQ(gap.error(), ErrorId::SpindleSpeedNoRange);
  auto unused = select_gear(sp, 1, 1000, 3u);
  ASSERT_FALSE(unused);
  EXPECT_EQ(unused.error(), ErrorId::SpindleGearStageInvalid);
  EXPECT_FALSE(select_gear(sp, 1, 1000, 9u));
  EXPECT_FALSE(select_gear(sp, 1, std::nan(""), std::nullopt));
  EXPECT_TRUE(gear_covers(sp, 2, 400));   // edges belong to the range
  EXPECT_TRUE(gear_covers(sp, 2, 800));
  EXPECT_FALSE(gear_covers(sp, 2, 800.5));
  EXPECT_FALSE(gear_covers(sp, 0, 100));
}

}  // namespace
}  // namespace nck::spindle
