// Numbers without floating-point noise (issue 48 item 4): what a person
// reads at the control's resolution, output files at 1e-6, no -0.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "nck/core/shown_number.hpp"

namespace nck {
namespace {

TEST(ShownNumber, PositionsAtTenthOfAMicrometre) {
  EXPECT_EQ(shown(23.47000000000009), 23.47);  // the nearest double to 23.47: prints as "23.47"
  EXPECT_EQ(shown(360.0002501519319), 360.0003);
  EXPECT_EQ(shown(901.1588535220199), 901.1589);
  EXPECT_EQ(shown(-1080.0000721220015), -1080.0001);
  EXPECT_EQ(shown(0.00005), 0.0001);  // half away from zero
  EXPECT_EQ(shown(-0.00005), -0.0001);
}

TEST(ShownNumber, NoNegativeZero) {
  EXPECT_FALSE(std::signbit(written(-4.440892098500626e-16)));
  EXPECT_FALSE(std::signbit(shown(-0.00004)));
}

TEST(ShownNumber, OutputFilesAtAMillionth) {
  EXPECT_EQ(written(0.3058678592690582), 0.305868);
  EXPECT_EQ(written(3.37609723160027e-05), 3.4e-05);
  EXPECT_EQ(written(901.1588535220199), 901.158854);
  EXPECT_EQ(written(33.999999999999716), 34.0);
  EXPECT_NEAR(written(14.142135623730951), 14.142135623730951, 5e-7);  // within a micrometre
}

TEST(ShownNumber, NonFiniteValuesPass) {
  EXPECT_TRUE(std::isnan(shown(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_EQ(shown(std::numeric_limits<double>::infinity()), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace nck
