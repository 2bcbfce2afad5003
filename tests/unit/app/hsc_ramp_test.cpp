// HSC takes the longest of the weighted ramp times in every phase (issue 44,
// item 3; TF5200 P-CHAN-00071). X with a_beschl 2,500 mm/s^2, a 50 ms ramp
// to build up the acceleration and 12.4 ms for the other three: the path's
// jerk stays within 2,500 / 0.05 = 50,000 mm/s^3 (each phase's own ramp gave
// 201,000 where the acceleration came back to 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;

TEST(HscRamp, TheLongestRampTimeBoundsEveryPhase) {
  const PatchedMachine m = patched_example("mill", "hsc-ramp", "x.lis",
                                           "getriebe[0].slope_profil.tr_beschl_ab 12400\n"
                                           "getriebe[0].slope_profil.tr_brems_zu 12400\n"
                                           "getriebe[0].slope_profil.tr_brems_ab 12400\n"
                                           "getriebe[0].dynamik.tr_min 10000");
  const auto dir = temp_dir("hsc-ramp-run");
  write(dir / "p.nc", "N10 G90 G0 X0 Y0 Z0\nN20 #SLOPE [TYPE=HSC]\nN30 G1 X100 F6000\nN40 M30\n");
  const CliResult c = run_nck("run " + m.dir.string() + " " + (dir / "p.nc").string() + " --trace " +
                              (dir / "t.csv").string() + " --trace-columns path.a,path.j");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  const auto lines = split(read_file(dir / "t.csv"), '\n');
  const auto head = split(lines.at(0), ',');
  const std::size_t ia = std::find(head.begin(), head.end(), "path.a") - head.begin();
  const std::size_t ij = std::find(head.begin(), head.end(), "path.j") - head.begin();
  ASSERT_LT(ij, head.size());
  double a_peak = 0, j_peak = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    const auto cols = split(lines[i], ',');
    a_peak = std::max(a_peak, std::fabs(std::stod(cols[ia])));
    j_peak = std::max(j_peak, std::fabs(std::stod(cols[ij])));
  }
  EXPECT_GT(a_peak, 2000);                  // the move reaches its acceleration
  EXPECT_LE(j_peak, 50000 * (1 + 1e-6));    // 2,500 / 0.05
  EXPECT_GT(j_peak, 40000);
}

}  // namespace
}  // namespace nck::app
