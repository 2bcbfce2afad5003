// An axis programmed twice (TF5200 20203) and the channel parameters that
// allow it: P-CHAN-00116 (G90/G91 acting on the positions after them) and
// P-CHAN-00148 (an axis several times: the last value under G90, the sum
// under G91). Block numbers from expressions are rounded (TF5200 "NC block
// numbers").
#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

DecoderConfig multi(bool dimensions, bool axes) {
  DecoderConfig c = default_config();
  c.multi_dimension_in_block = dimensions;
  c.multi_axes_in_block = axes;
  return c;
}

TEST(NcAxisDimensions, AxisTwiceIs20203InEveryForm) {
  for (const char* text : {"X1 Y2 X1\n", "C1=1 C1=2\n", "X1 X=2\n"}) {
    auto d = decode(text);
    const Diagnostic* e = d.find(ErrorId::NcAxisTwice);
    ASSERT_NE(e, nullptr) << text << dump(d);
    EXPECT_NE(e->message.find("P-CHAN-00148"), std::string::npos) << e->message;
  }
  EXPECT_TRUE(decode("X1 X2\n", multi(true, false)).has(ErrorId::NcAxisTwice));
}

TEST(NcAxisDimensions, RepeatedAxisLastUnderG90SumUnderG91) {
  auto d = decode("G90 X10 Y10 X2\nG91 Y10 Z20 Y1\nM30\n", multi(true, true));
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  ASSERT_EQ(d.blocks.size(), 3u);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[0], 2);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[1], 10);
  EXPECT_DOUBLE_EQ(*d.blocks[1].axes[1], 11);
  EXPECT_DOUBLE_EQ(*d.blocks[1].axes[2], 20);
}

TEST(NcAxisDimensions, G90AndG91InOneBlockNeedP116) {
  EXPECT_TRUE(decode("G90 G91 X1\n").has(ErrorId::NcModalConflict));
  auto d = decode("G90 G91 X1 Y2\nM30\n", multi(true, false));
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  EXPECT_FALSE(d.blocks[0].modal.absolute);
}

// One dimension per block: a position that would get another one than the
// block ends with is refused by name, never moved the wrong way.
TEST(NcAxisDimensions, MixedDimensionsAreRefused) {
  for (const char* text : {"G90 X10 G91 Y10\n", "X10 G91\n", "G91 X1 G90 Y2 G91\n"}) {
    auto d = decode(text, multi(true, true));
    const Diagnostic* e = d.find(ErrorId::NcUnsupported);
    ASSERT_NE(e, nullptr) << text << dump(d);
    EXPECT_NE(e->message.find("P-CHAN-00116"), std::string::npos) << e->message;
  }
  // G91 before every position, even with modal G90: one dimension.
  EXPECT_EQ(decode("X0\nG91 X1 Y1\nM30\n", multi(true, true)).errors(), 0u);
}

TEST(NcBlockNumbers, ComputedNumbersAreRounded) {
  auto d = decode("P123 = 7.5\nNP123 X1\nN[2.4] X2\nN[P123*100] X3\nM30\n");
  ASSERT_EQ(d.errors(), 0u) << dump(d);
  ASSERT_EQ(d.blocks.size(), 4u);
  EXPECT_EQ(d.blocks[0].n, 8);
  EXPECT_EQ(d.blocks[1].n, 2);
  EXPECT_EQ(d.blocks[2].n, 750);
  EXPECT_TRUE(decode("N[-1] X1\n").has(ErrorId::NcBadValue));
}

}  // namespace
}  // namespace nck::nc::test
