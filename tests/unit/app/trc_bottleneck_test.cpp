// Bottlenecks between blocks that are not neighbours (issue 13) through
// `nck run`: a dovetail groove whose opening is narrower than the tool
// while its bottom is wide enough, so every block keeps its direction but
// the tool-centre paths of its two walls cross; the same groove with a wide
// opening runs, on the points worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "trc_helpers.hpp"

namespace nck::app {
namespace {

using namespace trc_testing;

// Along Y0 with the tool (D1, 5 mm) left = above; at X20 a groove 20 deep
// whose walls lean outwards by 10 mm, its opening `open_mm` wide.
std::string groove(int open_mm) {
  const int right = 20 + open_mm;
  return "N10 G17 G90 G26 D1\nN20 G0 X-10 Y10\nN30 G41 G1 X0 Y0 F600\nN40 X20\nN50 X10 Y-20\nN60 X" +
         std::to_string(right + 10) + "\nN70 X" + std::to_string(right) + " Y0\nN80 X60\nN90 G40 G1 Y10\nN100 M30\n";
}

TEST(TrcBottleneck, NarrowDovetailOpeningStopsBeforeTheToolMoves) {
  // Opening 6 < 10: the wall paths cross at X23 Y-5.18 (the walls' offset
  // lines X = 24.47 + (Y + 2.24) / 2 and its mirror about X23).
  const TrcRun r = run_text("mill", "trc-bottleneck-narrow", groove(6));
  EXPECT_EQ(r.cli.exit_code, 1) << r.cli.output;
  ASSERT_EQ(r.errors.size(), 1u) << r.cli.output;
  EXPECT_EQ(r.errors[0]["id"], 930305);
  EXPECT_EQ(r.errors[0]["line"], 7);  // N70, the second wall
  EXPECT_NE(r.errors[0]["msg"].get<std::string>().find("line 5"), std::string::npos) << r.errors[0]["msg"];
  // Nothing of the contour ran: after the G0 the tool stayed at X-10 Y10.
  const std::size_t x = col(r, "X"), y = col(r, "Y");
  ASSERT_FALSE(r.rows.empty());
  for (const auto& row : r.rows) EXPECT_LE(row[x], 1e-9) << row[0];
  EXPECT_NEAR(r.rows.back()[x], -10, 1e-9);
  EXPECT_NEAR(r.rows.back()[y], 10, 1e-9);
}

TEST(TrcBottleneck, WideDovetailOpeningRuns) {
  // Opening 12 > 10: the wall paths would meet at X26 Y0.82, above both.
  const TrcRun r = run_text("mill", "trc-bottleneck-wide", groove(12));
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_TRUE(r.errors.empty());
  // Left wall X20 Y0 -> X10 Y-20: its normal to the left is (2, -1)/sqrt 5,
  // so its path starts at X20 + 2 sqrt 5, Y -sqrt 5 and meets the bottom's
  // path (Y-15) after 12.76 mm of its Y, i.e. 6.38 mm of X. The right wall
  // X42 Y-20 -> X32 Y0 is the mirror image about X26.
  const double s5 = std::sqrt(5.0);
  const double left_x = 20 + 2 * s5 - (15 - s5) / 2;
  expect_points(r, "X", "Y",
                {{40, 0, 5},
                 {50, 20 + 2 * s5, -s5},  // N40 and the corner arc about X20 Y0
                 {60, left_x, -15},
                 {70, 52 - left_x, -15},
                 {80, 32, 5},             // N70 and the corner arc about X32 Y0
                 {90, 60, 5},
                 {100, 60, 10}});
}

}  // namespace
}  // namespace nck::app
