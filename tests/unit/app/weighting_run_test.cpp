// G131/G133 through `nck run` on examples/mill (X a_beschl 2500 mm/s^2,
// feed ramp times 50 ms): under TRAPEZ, G131=80 G133=50 let the path
// accelerate with at most 2000 mm/s^2 and jerk 2000 / 0.025 = 80,000 mm/s^3
// (above the unweighted bound 50,000, so the shorter ramps are used), and
// #SLOPE DEFAULT then #SLOPE TRAPEZ brings back 2500 and 50,000.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "spindle_path_helpers.hpp"

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

// Issue 44 item 4: G131=300 asks X/Y for 7,500 mm/s^2 and Z for 6,000.
// TF5200 limits each weighted value to a_w_max (here X: 2,800 set in the
// list; Y, Z: a_max 3,000 and 2,500), warns 120033 at the weighting and runs
// on (nck before aborted with 930800). The axes accelerate with the limited
// values, never beyond them.
TEST(WeightingRun, AnAccelerationWeightingAboveAwMaxIsLimitedAndRunsOn) {
  const auto m = patched_example("mill", "weighting-limited", "x.lis", "getriebe[0].dynamik.a_w_max 2800");
  const PathRun r = run_text(m.dir.string(),
                             "N10 G90 G0 X0 Y0 Z0\nN20 G131=300\nN30 G1 X100 F12000\nN40 Y50\nN50 Z-20\n"
                             "N60 X0 Y0 Z0\nN70 M30\n",
                             "weighting-limited-run");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const auto warnings = r.of("warning");
  ASSERT_EQ(warnings.size(), 4u) << r.cli.output;  // X, Y, Z and S1's C axis (24,000 deg/s^2) at N20
  for (const json& w : warnings) {
    EXPECT_EQ(w["id"], 120033);
    EXPECT_EQ(w["line"], 2);
  }
  EXPECT_NE(r.cli.output.find("axis X: a_beschl 2500 at 300 % is 7500, above a_w_max 2800: 2800 used"),
            std::string::npos) << r.cli.output;
  EXPECT_GT(r.line_t(7), 0);  // N70 M30 is reached
  ASSERT_EQ(r.of("end").size(), 1u);
  EXPECT_EQ(r.of("end")[0]["reason"], "M30");
  const double a_w_max[] = {2800, 3000, 2500};
  const char* axes[] = {"X", "Y", "Z"};
  ASSERT_GE(r.line_t(3), 0);
  double peak[3] = {};
  // From the weighted moves on (N10's G0 accelerates with a_grenz).
  for (std::size_t i = r.index(r.line_t(3)) + 2; i < r.rows.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      auto p = [&](std::size_t row) { return r.rows[row].at(axes[k]); };
      const double a = (p(i) - 2 * p(i - 1) + p(i - 2)) / (kDt * kDt);
      ASSERT_LE(std::abs(a), a_w_max[k] + 3.0) << axes[k] << " at " << r.rows[i].at("t");  // + the trace's digits
      peak[k] = std::max(peak[k], std::abs(a));
    }
  for (int k = 0; k < 3; ++k) EXPECT_GT(peak[k], 0.9 * a_w_max[k]) << axes[k];  // the limited value is used
}

}  // namespace
}  // namespace nck::app
