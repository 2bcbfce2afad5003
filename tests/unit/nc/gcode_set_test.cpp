// GCode / GCodeSet: the enum's values are the G numbers, the set holds only
// non-modal codes and iterates in ascending G number order.
#include <gtest/gtest.h>

#include <vector>

#include "nck/nc/gcode.hpp"
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

std::vector<int> numbers(const GCodeSet& s) {
  std::vector<int> out;
  for (GCode g : s) out.push_back(g_number(g));
  return out;
}

TEST(GCode, ValuesAreTheGNumbers) {
  EXPECT_EQ(g_number(GCode::g0), 0);
  EXPECT_EQ(g_number(GCode::g33), 33);
  EXPECT_EQ(g_number(GCode::g100), 100);
  EXPECT_EQ(g_number(GCode::g332), 332);
}

TEST(GCodeSet, StartsEmpty) {
  GCodeSet s;
  EXPECT_TRUE(s.empty());
  EXPECT_EQ(s.size(), 0u);
  EXPECT_FALSE(s.has(GCode::g4));
  EXPECT_EQ(s.begin(), s.end());
}

TEST(GCodeSet, AddsNonModalCodesOnly) {
  GCodeSet s;
  EXPECT_TRUE(s.add(GCode::g92));
  EXPECT_FALSE(s.add(GCode::g1));   // modal: not held
  EXPECT_FALSE(s.add(GCode::g201)); // manual mode group is modal
  EXPECT_TRUE(s.has(GCode::g92));
  EXPECT_FALSE(s.has(GCode::g1));
  EXPECT_EQ(s.size(), 1u);
  EXPECT_TRUE(s.add(GCode::g92));  // adding twice keeps one
  EXPECT_EQ(s.size(), 1u);
}

TEST(GCodeSet, IteratesAscendingWhateverTheInsertionOrder) {
  GCodeSet s;
  s.add(GCode::g200);
  s.add(GCode::g4);
  s.add(GCode::g101);
  s.add(GCode::g74);
  EXPECT_EQ(numbers(s), (std::vector<int>{4, 74, 101, 200}));
}

TEST(GCodeSet, HoldsEveryListedCode) {
  GCodeSet all;
  for (GCode g : GCodeSet::kCodes) {
    EXPECT_TRUE(GCodeSet::is_nonmodal(g)) << g_number(g);
    EXPECT_TRUE(all.add(g));
  }
  EXPECT_EQ(all.size(), GCodeSet::kCodes.size());
  EXPECT_EQ(numbers(all), (std::vector<int>{4, 60, 61, 74, 92, 100, 101, 102, 106, 112, 130, 131, 132, 133, 134, 135, 136, 137, 167,
                              196, 200, 233}));
}

TEST(GCodeSet, HasAnyAndEquality) {
  constexpr GCodeSet values{GCode::g74, GCode::g92};
  static_assert(values.has(GCode::g74) && !values.has(GCode::g4));
  EXPECT_TRUE((GCodeSet{GCode::g92, GCode::g4}.has_any(values)));
  EXPECT_FALSE((GCodeSet{GCode::g4}.has_any(values)));
  EXPECT_FALSE(GCodeSet{}.has_any(values));
  EXPECT_EQ((GCodeSet{GCode::g92, GCode::g74}), values);
  EXPECT_NE(GCodeSet{GCode::g92}, values);
}

TEST(GCodeSet, DecoderCollectsTheBlocksNonModalCodes) {
  auto d = decode("G1 G92 X1\nG4 X2\nG0 X3\nM30\n");
  ASSERT_GE(d.blocks.size(), 3u) << dump(d);
  EXPECT_EQ(d.blocks[0].g_nonmodal, GCodeSet{GCode::g92});
  EXPECT_EQ(d.blocks[1].g_nonmodal, GCodeSet{GCode::g4});
  EXPECT_TRUE(d.blocks[2].g_nonmodal.empty());
}

TEST(GCodeSet, ManualModeIsKeptAsTheBlocksManualG) {
  auto d = decode("G201 X1\nG202\nM30\n");
  ASSERT_GE(d.blocks.size(), 2u) << dump(d);
  EXPECT_EQ(d.blocks[0].manual_g, GCode::g201);
  EXPECT_EQ(d.blocks[1].manual_g, GCode::g202);
  EXPECT_TRUE(d.blocks[0].g_nonmodal.empty());
}

}  // namespace
}  // namespace nck::nc::test
