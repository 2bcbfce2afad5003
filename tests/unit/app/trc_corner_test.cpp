// Outside-corner transitions of tool radius compensation (issue 13):
// G25 (default) extends the offset elements' tangents, G26 inserts an arc
// of the tool radius (the arcs are checked in trc_test.cpp). Through `nck
// run`, against points worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "trc_helpers.hpp"

namespace nck::app {
namespace {

using namespace trc_testing;

TEST(TrcCorner, G25RectangleHasSharpCornersAtTheOffsetIntersections) {
  // The rectangle 60 x 40 of contour_trc.nc without G26: tool left going
  // clockwise (outside), radius 5: the path is the rectangle -5..65 x -5..45.
  const TrcRun r = run_text("mill", "trc-g25-rect",
                            "N10 G17 G90 D1\nN20 G0 X-20 Y-20\nN40 G41 G1 X0 Y0 F600\nN50 Y40\nN60 X60\nN70 Y0\n"
                            "N80 X0\nN90 G40 G1 X-20 Y-20\nN100 M30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_TRUE(r.errors.empty());
  expect_points(r, "X", "Y", {{50, -5, 0}, {60, -5, 45}, {70, 65, 45}, {80, 65, -5}, {90, 0, -5}, {100, -20, -20}});
  // Straight sides only: N60 runs along Y45 all the way.
  const std::size_t x = col(r, "X"), y = col(r, "Y");
  for (const auto& row : between(r, 60, 70)) EXPECT_NEAR(row[y], 45, 1e-9) << row[x];
}

TEST(TrcCorner, G25TurnBeyond90DegreesExtendsBothByTheRadiusAndJoinsThem) {
  // G42 along +X to X40, then back to X0 Y20: a left turn of 153.4 deg
  // with the tool right = outside. The line along Y-5 goes on by the tool
  // radius to X45; the diagonal's offset (its left normal (-1, -2)/sqrt 5
  // times -5 = (sqrt 5, 2 sqrt 5)) starts at X40+sqrt5 Y2sqrt5, taken back
  // by 5 mm along (-2, 1)/sqrt 5: X40+3sqrt5 Y sqrt5; a line joins the two.
  const double s5 = std::sqrt(5.0);
  const TrcRun r = run_text("mill", "trc-g25-acute",
                            "N10 G17 G90 D1\nN20 G0 X-10 Y-20\nN30 G42 G1 X0 Y0 F600\nN40 X40\nN50 X0 Y20\n"
                            "N60 G40 G1 X-10 Y30\nN70 M30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_TRUE(r.errors.empty());
  expect_points(r, "X", "Y", {{40, 0, -5}, {50, 40 + 3 * s5, s5}, {60, s5, 20 + 2 * s5}, {70, -10, 30}});
  const std::size_t x = col(r, "X"), y = col(r, "Y");
  double nearest_corner = 1e9, nearest_programmed = 1e9;
  for (const auto& row : between(r, 40, 50)) {
    nearest_corner = std::min(nearest_corner, std::hypot(row[x] - 45, row[y] + 5));
    // Never nearer to the programmed corner X40 Y0 than the tool radius.
    nearest_programmed = std::min(nearest_programmed, std::hypot(row[x] - 40, row[y]));
  }
  EXPECT_LT(nearest_corner, kTol);  // it passes X45 Y-5
  EXPECT_GE(nearest_programmed, 5 - 1e-6);
  // The joining line: from X45 Y-5 to X40+3sqrt5 Y sqrt5, rows on it.
  int on_join = 0;
  for (const auto& row : between(r, 40, 50))
    if (row[x] > 45 + 1e-6) {
      const double cross = (row[x] - 45) * (s5 + 5) - (row[y] + 5) * (3 * s5 - 5);
      EXPECT_NEAR(cross / std::hypot(3 * s5 - 5, s5 + 5), 0, 1e-6);
      ++on_join;
    }
  EXPECT_GT(on_join, 100);  // 7.4 mm at <= 10 mm/s
}

TEST(TrcCorner, G26InsertsAnArcG25IsTheDefaultAgain) {
  // G26 then G25 on the same kind of corner: the arc about X0 Y40 first,
  // the sharp corner at X65 Y45 after G25.
  const TrcRun r = run_text("mill", "trc-g25-g26",
                            "N10 G17 G90 G26 D1\nN20 G0 X-20 Y-20\nN40 G41 G1 X0 Y0 F600\nN50 Y40\nN60 X60\n"
                            "N70 G25 Y0\nN80 X0\nN90 G40 G1 X-20 Y-20\nN100 M30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  expect_points(r, "X", "Y", {{60, 0, 45}, {70, 65, 45}, {80, 65, -5}});
  EXPECT_EQ(r.final_state["channels"][0]["trc"], "G40");
}

}  // namespace
}  // namespace nck::app
