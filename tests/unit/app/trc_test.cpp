// Tool radius compensation G40/G41/G42 through `nck run` (issue 13): the
// tool-centre path in the trace against points worked out by hand on a
// rectangle, a rounded rectangle, a pocket (examples/mill/contour_trc.nc,
// D1 = 5 mm) and a lathe profile (examples/lathe/profile_trc.nc, D4 =
// 0.8 mm), and the errors that stop a program before the tool gets there.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "trc_helpers.hpp"

namespace nck::app {
namespace {

using namespace trc_testing;

TEST(Trc, MillContoursFollowTheToolCentrePathsWorkedOutByHand) {
  const auto dir = temp_dir("trc-mill");
  const TrcRun r = run("mill", root() + "/examples/mill/contour_trc.nc", dir);
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_TRUE(r.errors.empty());
  // 1. rectangle 60 x 40, tool left going clockwise = outside, radius 5
  expect_points(r, "X", "Y",
                {{50, -5, 0},     // N40 links onto X-5 (square to N50's direction +Y)
                 {60, 0, 45},     // N50 ends at X-5 Y40, the corner arc R5 about X0 Y40 to X0 Y45
                 {70, 65, 40},    // after N60 and the arc about X60 Y40
                 {80, 60, -5},    // after N70 and the arc about X60 Y0
                 {90, 0, -5},     // N80 ends square to its end: G40 follows
                 {110, -20, -20}});  // N90 leaves to the programmed point
  // 2. rounded rectangle R8: the tool follows at R13, tangent transitions
  expect_points(r, "X", "Y",
                {{120, -5, 8}, {130, -5, 32}, {140, 8, 45}, {150, 52, 45}, {160, 65, 32},
                 {170, 65, 8}, {180, 52, -5}, {190, 8, -5}, {200, -5, 8}, {210, -20, -20}});
  // 3. pocket, tool left going counter-clockwise = inside: corners at 5 mm from both walls
  expect_points(r, "X", "Y",
                {{320, 30, 5}, {330, 55, 5}, {340, 55, 35}, {350, 5, 35}, {360, 5, 5}, {370, 30, 5},
                 {380, 30, 20}});
  const std::size_t x = col(r, "X"), y = col(r, "Y");
  // The corner arc after N50: every point above Y40 is 5 mm from the corner X0 Y40.
  int on_arc = 0;
  for (const auto& row : between(r, 50, 60))
    if (row[y] > 40 + 1e-6) {
      EXPECT_NEAR(std::hypot(row[x] - 0, row[y] - 40), 5, 1e-6);
      ++on_arc;
    }
  EXPECT_GT(on_arc, 100);  // 7.85 mm of arc at <= 10 mm/s
  // N130 (programmed R8 about X8 Y32) runs at R13.
  for (const auto& row : between(r, 130, 140)) EXPECT_NEAR(std::hypot(row[x] - 8, row[y] - 32), 13, 1e-6);
  // The pocket's walls are never nearer than the tool radius.
  for (const auto& row : between(r, 320, 380)) {
    EXPECT_GE(row[x], 5 - 1e-6);
    EXPECT_LE(row[x], 55 + 1e-6);
    EXPECT_GE(row[y], 5 - 1e-6);
    EXPECT_LE(row[y], 35 + 1e-6);
  }
  EXPECT_EQ(r.final_state["channels"][0]["trc"], "G40");
  EXPECT_EQ(r.final_state["channels"][0]["tool"]["d"], 1);
  EXPECT_DOUBLE_EQ(r.final_state["channels"][0]["tool"]["radius_mm"].get<double>(), 5.0);
}

// The per-axis limits of the continuous path hold on compensated paths,
// inserted corner arcs included (mill: max_speed_mm_s 500 mm/s, a_max X/Y 3000 mm/s^2).
TEST(Trc, AxisLimitsHoldOnTheCompensatedPath) {
  const TrcRun r = run_text("mill", "trc-limits",
                         "N10 G17 G90 G26 D1\nN20 G0 X-20 Y-20\n"
                         "N30 G41 G1 X0 Y0 F20000\nN40 Y40\nN50 X60\nN60 G2 X60 Y0 I0 J-20\nN70 G1 X0\n"
                         "N80 G40 G1 X-20 Y-20\nN90 M30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const double dt = 0.001;
  for (const std::string axis : {"X", "Y"}) {
    const std::size_t c = col(r, axis);
    for (std::size_t i = 2; i < r.rows.size(); ++i) {
      const double v1 = (r.rows[i][c] - r.rows[i - 1][c]) / dt, v0 = (r.rows[i - 1][c] - r.rows[i - 2][c]) / dt;
      ASSERT_LE(std::abs(v1), 500 + 0.01) << axis << " row " << i;
      // + 5 mm/s^2: the trace's printed digits (as in the continuous-path tests)
      ASSERT_LE(std::abs(v1 - v0) / dt, 3000 + 5.0) << axis << " row " << i;
    }
  }
}

TEST(Trc, InsideArcSmallerThanTheToolStopsBeforeTheToolMoves) {
  // A pocket corner rounded R3 with a 5 mm tool on its inside: R3 - 5 < 0.
  const TrcRun r = run_text("mill", "trc-small-arc",
                         "N10 G17 G90 D1\nN20 G0 X30 Y20\nN30 G41 G1 Y0 F600\nN40 X57\n"
                         "N50 G3 X60 Y3 R3\nN60 G1 Y40\nN70 G40 G1 X30 Y20\nN80 M30\n");
  EXPECT_EQ(r.cli.exit_code, 1) << r.cli.output;
  ASSERT_EQ(r.errors.size(), 1u) << r.cli.output;
  EXPECT_EQ(r.errors[0]["id"], 90017);
  EXPECT_EQ(r.errors[0]["line"], 5);
  // Neither the approach nor the line into the arc ran: after the G0 the
  // tool stayed at X30 Y20.
  const std::size_t x = col(r, "X"), y = col(r, "Y");
  ASSERT_FALSE(r.rows.empty());
  for (const auto& row : r.rows) EXPECT_FALSE(row[x] > 30 - 1e-9 && row[y] < 20 - 1e-9) << row[0];
  EXPECT_NEAR(r.rows.back()[x], 30, 1e-9);
  EXPECT_NEAR(r.rows.back()[y], 20, 1e-9);
}

TEST(Trc, SlotNarrowerThanTheToolIsABottleneck) {
  // Along Y0 with a slot 6 mm wide and 10 deep at X20..26; tool radius 5 on
  // the open side: the slot's bottom would run backwards (X25 -> X21).
  const TrcRun r = run_text("mill", "trc-slot",
                         "N10 G17 G90 D1\nN20 G0 X-10 Y10\nN30 G41 G1 X0 Y0 F600\nN40 X20\nN50 Y-10\n"
                         "N60 X26\nN70 Y0\nN80 X50\nN90 G40 G1 Y20\nN100 M30\n");
  EXPECT_EQ(r.cli.exit_code, 1) << r.cli.output;
  ASSERT_EQ(r.errors.size(), 1u) << r.cli.output;
  EXPECT_EQ(r.errors[0]["id"], 930300);
  EXPECT_EQ(r.errors[0]["line"], 6);  // N60, the slot's bottom
  // The tool went along Y5 to X20 and no farther: never over the slot.
  const std::size_t x = col(r, "X"), y = col(r, "Y");
  for (const auto& row : r.rows) {
    EXPECT_LE(row[x], 20 + 1e-9);
    if (row[x] > 0) {
      EXPECT_NEAR(row[y], 5, 1e-9);
    }
  }
}

TEST(Trc, FunctionsNotAllowedWhileTrcIsSelected) {
  struct Case {
    std::string block;
    std::uint32_t id;
  } cases[] = {
      {"#CS ON [1][0,0,0,0,0,10]", 20802}, {"#TLC ON [5]", 20671}, {"#PSET X0", 20608},
      {"G100 X100", 20049},             {"G18", 20133},        {"G92 X0", 930301},
  };
  for (const Case& c : cases) {
    const TrcRun r = run_text("mill", "trc-forbidden",
                           "N10 G17 G90 D1\nN20 G0 X0 Y0\nN30 G41 G1 X10 F600\nN40 X20\nN50 " + c.block +
                               "\nN60 X30\nN70 G40 X40\nN80 M30\n");
    ASSERT_EQ(r.errors.size(), 1u) << c.block << r.cli.output;
    EXPECT_EQ(r.errors[0]["id"], c.id) << c.block;
    EXPECT_EQ(r.errors[0]["line"], 5) << c.block;
  }
}

// A block that repeats where the plane axes stand has no motion data for
// the compensation: like a block without plane axes it waits behind the last
// element, and a ninth in a row is 90011 (issue 45: 20,000 of them held
// 14 KB each and the run slowed faster than linearly).
TEST(Trc, RepeatedEndPointsCountAsBlocksWithoutPlaneMotion) {
  auto program = [](int repeats) {
    std::string text = "N10 G17 G90 D1\nN20 G0 X-10 Y-10\nN30 G41 G1 X0 Y0 F600\nN40 Y40\n";
    for (int i = 0; i < repeats; ++i) text += "Y40\n";
    return text + "X60\nG40 G1 X80 Y80\nM30\n";
  };
  const TrcRun eight = run_text("mill", "trc-repeat-8", program(8));
  ASSERT_EQ(eight.cli.exit_code, 0) << eight.cli.output;
  expect_points(eight, "X", "Y", {{40, -5, 0}});  // N40 runs +Y with the tool on its left
  ASSERT_FALSE(eight.rows.empty());
  EXPECT_NEAR(eight.rows.back()[col(eight, "X")], 80, 1e-9);
  EXPECT_NEAR(eight.rows.back()[col(eight, "Y")], 80, 1e-9);
  const TrcRun nine = run_text("mill", "trc-repeat-9", program(9));
  EXPECT_EQ(nine.cli.exit_code, 1) << nine.cli.output;
  ASSERT_EQ(nine.errors.size(), 1u) << nine.cli.output;
  EXPECT_EQ(nine.errors[0]["id"], 90011);
  EXPECT_EQ(nine.errors[0]["line"], 13);  // the ninth repeat
}

TEST(Trc, SelectionInACircleAndRadiusChangeInACircleAreErrors) {
  const TrcRun sel = run_text("mill", "trc-sel-arc", "N10 G17 G90 D1\nN20 G0 X0 Y0\nN30 G41 G2 X20 Y0 R10 F600\nN40 M30\n");
  ASSERT_EQ(sel.errors.size(), 1u) << sel.cli.output;
  EXPECT_EQ(sel.errors[0]["id"], 90008);
  const TrcRun chg = run_text("mill", "trc-d-arc",
                           "N10 G17 G90 D1\nN20 G0 X0 Y0\nN30 G41 G1 X10 F600\nN40 X20\nN50 D2 G2 X40 Y0 R10\n"
                           "N60 G40 G1 X50\nN70 M30\n");
  ASSERT_EQ(chg.errors.size(), 1u) << chg.cli.output;
  EXPECT_EQ(chg.errors[0]["id"], 90047);
  EXPECT_EQ(chg.errors[0]["line"], 5);
}

TEST(Trc, NewRadiusWhileActiveLinksOnALine) {
  // D1 (5 mm) then D2 (4.25 mm) along +X, tool left: the D2 line leads from
  // Y5 to Y4.25 square to the next element's start.
  const TrcRun r = run_text("mill", "trc-d-change",
                         "N10 G17 G90 D1\nN20 G0 X0 Y-10\nN30 G41 G1 Y0 F600\nN40 X20\nN50 D2 X30\n"
                         "N60 X50\nN70 G40 G1 Y-10\nN80 M30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  // N30 goes up +Y onto X0; the next element runs +X, so it ends at X0 Y5.
  expect_points(r, "X", "Y", {{40, 0, 5}, {50, 20, 5}, {60, 30, 4.25}, {70, 50, 4.25}, {80, 50, -10}});
}

TEST(Trc, IncrementalWordsAreRewrittenAsIncrements) {
  // The rectangle of contour_trc.nc in G91, its right side a half circle
  // R20 (tangent to top and bottom): the tool runs it at R25.
  const TrcRun r = run_text("mill", "trc-g91",
                            "N10 G17 G90 G26 D1\nN20 G0 X-20 Y-20\nN30 G91 G41 G1 X20 Y20 F600\nN40 Y40\nN50 X60\n"
                            "N60 G2 X0 Y-40 I0 J-20\nN70 G1 X-60\nN80 G40 X-20 Y-20\nN90 G90 G0 X0 Y0\nN100 M30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  expect_points(r, "X", "Y", {{40, -5, 0}, {50, 0, 45}, {60, 60, 45}, {70, 60, -5}, {80, 0, -5}, {90, -20, -20}});
  const std::size_t x = col(r, "X"), y = col(r, "Y");
  for (const auto& row : between(r, 60, 70)) EXPECT_NEAR(std::hypot(row[x] - 60, row[y] - 20), 25, 1e-6);
}

TEST(Trc, LatheProfileWithChamferAndRadius) {
  const auto dir = temp_dir("trc-lathe");
  const TrcRun r = run("lathe", root() + "/examples/lathe/profile_trc.nc", dir);
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_TRUE(r.errors.empty());
  // G42 in the Z X plane, nose radius 0.8, X in radius (the program's
  // diameters halved). The nose centre S runs 0.8 off the contour; tool 4
  // has cutting-edge position 2, so the offsets (and the trace) follow the
  // theoretical tip P = S + (-0.8, -0.8) in (Z, X). Chamfer 45 deg: S is
  // 0.8 / sqrt(2) off it in Z and X.
  const double h = 0.8 / std::sqrt(2.0), e = 0.8;
  expect_points(r, "Z", "X",
                {{50, 0 + h - e, 8 + h - e},  // N40 links onto the chamfer's offset start
                 {60, -2 - e, 10.8 - e},      // N50 + the arc R0.8 about Z-2 X10 (outside corner)
                 {70, -20 - e, 10},           // N60, cylinder D20: P on X10 (radius)
                 {80, -24.2 - e, 15 - e},     // N70, the fillet R5 run at R4.2 about Z-20 X15
                 {90, -25 - e, 20.8 - e},     // N80 face + the arc about Z-25 X20
                 {100, -40 - e, 20},          // N90 ends square to its end
                 {110, -40, 25}});            // N100 G40: P on the programmed X50 (diameter)
  const std::size_t z = col(r, "Z"), x = col(r, "X");
  // The fillet: S at 4.2 from its centre Z-20 X15.
  for (const auto& row : between(r, 70, 80)) EXPECT_NEAR(std::hypot(row[z] + e + 20, row[x] + e - 15), 4.2, 1e-6);
  // The chamfer's corner arc keeps S 0.8 mm from the corner Z-2 X10.
  for (const auto& row : between(r, 50, 60))
    if (row[z] < -2 + h - e - 1e-6) {
      EXPECT_NEAR(std::hypot(row[z] + e + 2, row[x] + e - 10), 0.8, 1e-6);
    }
  // Longitudinal cut (N60, D20) and end face (N80 at Z-25, before its
  // corner arc): the tip P touches the programmed line.
  int on_line = 0, on_face = 0;
  for (const auto& row : between(r, 60, 70)) {
    EXPECT_NEAR(row[x], 10, 1e-9) << row[0];
    ++on_line;
  }
  for (const auto& row : between(r, 80, 90))
    if (row[x] <= 20 - e + 1e-9) {
      EXPECT_NEAR(row[z], -25, 1e-9) << row[0];
      ++on_face;
    }
  EXPECT_GT(on_line, 1000);  // 18 mm at F200 = 3.3 mm/s
  EXPECT_GT(on_face, 100);
  EXPECT_EQ(r.final_state["channels"][0]["trc"], "G40");
  EXPECT_EQ(r.final_state["channels"][0]["tool"]["d"], 4);
}

}  // namespace
}  // namespace nck::app
