// G130...G134, G233 as words (TF5200 acceleration and ramp-time weightings):
// G131=/G133=/G134=/G233= carry their percentage, G130/G132 take theirs
// from the axis words (which then are no motion target and no length), and
// malformed weightings are 920202 with file and line.
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

const Block& block_n(const Decoded& d, std::int64_t n) {
  for (const Block& b : d.blocks)
    if (b.n == n) return b;
  static const Block kNone;
  ADD_FAILURE() << "no block N" << n << "\n" << dump(d);
  return kNone;
}

TEST(WeightingSyntax, GroupWeightingsCarryTheirPercentage) {
  const auto d = decode("N10 G131=50\nN20 G133 = 25.5\nN30 g134=150 G233=200\nN40 G1 X1 F100\nM30\n");
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  const Block& b10 = block_n(d, 10);
  EXPECT_TRUE(b10.g_nonmodal.has(GCode::g131));
  EXPECT_DOUBLE_EQ(b10.group_weight(GroupWeight::g131), 50);
  EXPECT_DOUBLE_EQ(block_n(d, 20).group_weight(GroupWeight::g133), 25.5);
  const Block& b30 = block_n(d, 30);
  EXPECT_DOUBLE_EQ(b30.group_weight(GroupWeight::g134), 150);
  EXPECT_DOUBLE_EQ(b30.group_weight(GroupWeight::g233), 200);
  EXPECT_FALSE(block_n(d, 40).g_nonmodal.has(GCode::g131));  // not modal in the block: preparation keeps it
}

TEST(WeightingSyntax, PerAxisWeightingsAreAxisWordsInPercentEvenInInch) {
  const auto d = decode("N10 G70 G130 X70 Y120\nN20 G132 Z40\nM30\n");
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  const Block& b10 = block_n(d, 10);
  EXPECT_TRUE(b10.g_nonmodal.has(GCode::g130));
  EXPECT_DOUBLE_EQ(*b10.axes[0], 70);  // not 70 inch = 1778 mm
  EXPECT_DOUBLE_EQ(*b10.axes[1], 120);
  EXPECT_DOUBLE_EQ(*block_n(d, 20).axes[2], 40);
}

// #SLOPE DEFAULT makes no block: the next block carries it, once.
TEST(WeightingSyntax, SlopeDefaultIsCarriedByTheNextBlock) {
  const auto d = decode("N5 G1 X0 F100\nN10 #SLOPE [TYPE=TRAPEZ]\nN20 #SLOPE DEFAULT\nN30 X1\nN40 X2\nM30\n");
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  EXPECT_FALSE(block_n(d, 5).slope_default);
  EXPECT_TRUE(block_n(d, 30).slope_default);
  EXPECT_FALSE(block_n(d, 40).slope_default);
}

TEST(WeightingSyntax, MalformedWeightingsNameFileAndLine) {
  for (const char* bad : {"G131 50", "G133", "G131=0", "G133=-10", "G134=0", "G233=[1/0]", "G132", "G130",
                          "G130 X0", "G132 X-5", "G130 X70 G131=50", "G132 X50 G133=50", "G130 X70 G132 Y50"}) {
    const auto d = decode(std::string("G1 X1 F100\n") + bad + "\nM30\n");
    const Diagnostic* e = d.find(ErrorId::NcDynWeighting);
    if (!e) {
      EXPECT_GT(d.errors(), 0u) << bad;  // [1/0]: the expression's own error
      continue;
    }
    EXPECT_EQ(e->loc.line, 2u) << bad;
    EXPECT_NE(e->loc.file.find("prog.nc"), std::string::npos) << bad;
  }
  EXPECT_TRUE(decode("G131 50\n").has(ErrorId::NcDynWeighting));
  EXPECT_TRUE(decode("G131=0\n").has(ErrorId::NcDynWeighting));
  EXPECT_EQ(decode("G130 S50\nM30\n").errors(), 0u);  // the main spindle's weighting
}

}  // namespace
}  // namespace nck::nc::test
