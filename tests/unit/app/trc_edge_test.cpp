// Tool tip radius compensation with the cutting-edge position of a turning
// tool (tool list wz[i].srk_lage, issue 13) through `nck run`: the
// theoretical tip P, to which the offsets are measured, follows the
// program without compensation and runs at P = S + R * direction(position)
// with it (S the nose centre on the offset contour; the directions in
// motion/cutting_edge.hpp). The general lathe profile is in trc_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "trc_helpers.hpp"

namespace nck::app {
namespace {

using namespace trc_testing;

// Tool 6 of a copy of the lathe: a turning tool, nose radius 0.8, position `pos`.
std::filesystem::path lathe_with_tool6(const std::string& name, const std::string& pos) {
  return patched_example("lathe", name, "tools.lis",
                         "wz[6].typ 1\nwz[6].radius 8000\nwz[6].srk_lage " + pos)
      .dir;
}

TEST(TrcEdge, EveryPositionShiftsTheTipFromTheNoseCentre) {
  // Along D20 (X10 in radius) towards the chuck with G42: S runs at X10.8,
  // and ends square to the line at Z-10 before G40 leaves to X15 Z-10.
  // Before G42 the tip P stands on the programmed X12 Z2.
  const double dz[] = {0, 1, -1, -1, 1, 1, 0, -1, 0, 0};  // index = position
  const double dx[] = {0, -1, -1, 1, 1, 0, -1, 0, 1, 0};
  for (int pos = 1; pos <= 9; ++pos) {
    const auto m = lathe_with_tool6("trc-edge-" + std::to_string(pos), std::to_string(pos));
    const TrcRun r = run_text(m.string(), "trc-edge-run",
                              "N10 G18 G90 G51 G94 D6\nN20 G0 X24 Z2\nN30 G42 G1 X20 Z0 F600\nN40 Z-10\n"
                              "N50 G40 G1 X30\nN60 M30\n");
    ASSERT_EQ(r.cli.exit_code, 0) << pos << r.cli.output;
    const double ez = 0.8 * dz[pos], ex = 0.8 * dx[pos];
    expect_points(r, "Z", "X",
                  {{30, 2, 12},                  // G40: P on the programmed point
                   {40, 0 + ez, 10.8 + ex},      // the link ends square to N40 at Z0
                   {50, -10 + ez, 10.8 + ex},    // N40 ends square to its end
                   {60, -10, 15}});              // N50 G40: P on the programmed point again
    for (const auto& row : between(r, 40, 50)) EXPECT_NEAR(row[col(r, "X")], 10.8 + ex, 1e-9) << pos;
  }
}

TEST(TrcEdge, PositionOutsideOneToNineIsAConfigError) {
  const auto [dir, line] = patched_example("lathe", "trc-edge-range", "tools.lis", "wz[6].srk_lage 10");
  const CliResult r = run_nck("check " + dir.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("tools.lis:" + std::to_string(line) + ": error 910004:"), std::string::npos) << r.output;
}

TEST(TrcEdge, TurningToolPositionOutsideTheZXPlaneIsAnError) {
  // A turning tool with position 3 under G41 in G17 on the mill: its
  // positions are defined in Z X only.
  const auto m =
      patched_example("mill", "trc-edge-g17", "tools.lis", "wz[6].typ 1\nwz[6].radius 8000\nwz[6].srk_lage 3");
  const TrcRun r = run_text(m.dir.string(), "trc-edge-g17-run",
                            "N10 G17 G90 D6\nN20 G0 X0 Y0\nN30 G41 G1 X10 F600\nN40 X20\nN50 G40 X30\nN60 M30\n");
  EXPECT_EQ(r.cli.exit_code, 1) << r.cli.output;
  ASSERT_EQ(r.errors.size(), 1u) << r.cli.output;
  EXPECT_EQ(r.errors[0]["id"], 930304);
  EXPECT_EQ(r.errors[0]["line"], 3);
  // A milling tool (typ 0) with the same key is not shifted: the position
  // belongs to turning tools only.
  const auto mill = patched_example("mill", "trc-edge-mill", "tools.lis", "wz[6].radius 50000\nwz[6].srk_lage 3");
  const TrcRun ok = run_text(mill.dir.string(), "trc-edge-mill-run",
                             "N10 G17 G90 D6\nN20 G0 X0 Y-10\nN30 G41 G1 Y0 F600\nN40 X20\nN50 G40 Y-10\nN60 M30\n");
  ASSERT_EQ(ok.cli.exit_code, 0) << ok.cli.output;
  expect_points(ok, "X", "Y", {{40, 0, 5}, {50, 20, 5}, {60, 20, -10}});
}

}  // namespace
}  // namespace nck::app
