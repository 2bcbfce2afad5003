// G70: the decoder hands out every length in mm; values that are not
// lengths (dwell time, homing order, G101 factor, angles) stay as written.
#include <gtest/gtest.h>

#include <variant>

#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

TEST(InchToMm, MotionWordsAndFeedComeOutInMm) {
  auto d = decode("G70 G1 X1 Y-2 F10\nG2 X0 Y0 I0.5 J0\nG71 X1\nM30\n");
  ASSERT_GE(d.blocks.size(), 3u) << dump(d);
  EXPECT_TRUE(d.blocks[0].modal.inch);  // kept as information
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[0], 25.4);
  EXPECT_DOUBLE_EQ(*d.blocks[0].axes[1], -50.8);
  EXPECT_DOUBLE_EQ(d.blocks[0].modal.feed_mm_min, 254);
  EXPECT_DOUBLE_EQ(*d.blocks[1].ijk[0], 12.7);
  EXPECT_DOUBLE_EQ(*d.blocks[2].axes[0], 1);  // G71: as programmed
}

TEST(InchToMm, G92OffsetAndPsetAreLengths) {
  auto d = decode("G70\nG92 X2\n#PSET X1\nM30\n");
  ASSERT_GE(d.blocks.size(), 3u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[1].axes[0], 50.8);
  const auto* pset = std::get_if<PSet>(&*d.blocks[2].hash);
  ASSERT_NE(pset, nullptr);
  ASSERT_EQ(pset->axes.size(), 1u);
  EXPECT_DOUBLE_EQ(pset->axes[0].second, 25.4);
}

TEST(InchToMm, ValuesThatAreNoLengthsStay) {
  auto d = decode("G70\nG4 X2\nG74 X1 Y2\nG101 X0.5\nM30\n");
  ASSERT_GE(d.blocks.size(), 4u) << dump(d);
  EXPECT_DOUBLE_EQ(*d.blocks[1].dwell_s, 2);
  EXPECT_DOUBLE_EQ(*d.blocks[2].axes[1], 2);
  EXPECT_DOUBLE_EQ(*d.blocks[3].axes[0], 0.5);
}

}  // namespace
}  // namespace nck::nc::test
