// G131/G133 through `nck run` on examples/mill (X a_beschl 2500 mm/s^2,
// feed ramp times 50 ms): under TRAPEZ, G131=80 G133=50 let the path
// accelerate with at most 2000 mm/s^2 and jerk 2000 / 0.025 = 80,000 mm/s^3
// (above the unweighted bound 50,000, so the shorter ramps are used), and
// #SLOPE DEFAULT then #SLOPE TRAPEZ brings back 2500 and 50,000.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;

struct Peaks {
  double a = 0, j = 0;
};

TEST(WeightingRun, WeightedAccelerationAndRampTimesBoundTheProfile) {
  const auto dir = temp_dir("weighting-run");
  const std::string prog =
      "N10 G17 G90 G0 X0 Y0 Z0\nN20 #SLOPE [TYPE=TRAPEZ]\nN30 G131=80 G133=50\nN40 G1 X100 F12000\nN50 X0\n"
      "N60 #SLOPE DEFAULT\nN70 #SLOPE [TYPE=TRAPEZ]\nN80 X100\nN90 X0\nN100 M30\n";
  write(dir / "p.nc", prog);
  const CliResult c = run_nck("run " + mill() + " " + (dir / "p.nc").string() + " --trace " + (dir / "t.csv").string() +
                              " --events " + (dir / "e.jsonl").string() + " --trace-columns path.a,path.j");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  double t40 = -1, t80 = -1;
  for (const nlohmann::json& e : read_jsonl(dir / "e.jsonl")) {
    if (e["ev"] != "block" || e["n"].is_null()) continue;
    if (e["n"].get<long>() == 40) t40 = e["t"];
    if (e["n"].get<long>() == 80) t80 = e["t"];
  }
  ASSERT_GE(t40, 0);
  ASSERT_GT(t80, t40);
  const auto lines = split(read_file(dir / "t.csv"), '\n');
  const auto head = split(lines.at(0), ',');
  const std::size_t ia = std::find(head.begin(), head.end(), "path.a") - head.begin();
  const std::size_t ij = std::find(head.begin(), head.end(), "path.j") - head.begin();
  ASSERT_LT(ij, head.size());
  Peaks weighted, plain;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    const auto cols = split(lines[i], ',');
    const double t = std::stod(cols[0]);
    // The differences reach back two cycles: N50's last ramp shows in N80's first rows.
    if (t < t40 - 1e-9 || (t >= t80 - 1e-9 && t < t80 + 0.003 - 1e-9)) continue;
    Peaks& p = t < t80 - 1e-9 ? weighted : plain;
    p.a = std::max(p.a, std::fabs(std::stod(cols[ia])));
    p.j = std::max(p.j, std::fabs(std::stod(cols[ij])));
  }
  EXPECT_LE(weighted.a, 2000 * (1 + 1e-9));
  EXPECT_GT(weighted.a, 1900);
  EXPECT_LE(weighted.j, 80000 * (1 + 1e-6));
  EXPECT_GT(weighted.j, 60000);
  EXPECT_LE(plain.a, 2500 * (1 + 1e-9));
  EXPECT_GT(plain.a, 2400);
  EXPECT_LE(plain.j, 50000 * (1 + 1e-6));
  EXPECT_GT(plain.j, 40000);
}

}  // namespace
}  // namespace nck::app
