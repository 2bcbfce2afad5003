// `nck run --trace-columns path.v,path.a,path.j` (docs/cli.md): the default trace is
// unchanged without it; with it the path velocity, acceleration and jerk follow the
// default columns, and on examples/mill/slope.nc the jerk of the TRAPEZ pass
// stays within a/tr (X/Y a_beschl 2500 mm/s^2, ramp times 50 ms: 50,000
// mm/s^3) while the STEP pass jumps far beyond it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;

struct SlopeRun {
  CliResult cli;
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::vector<double> square_t;  // starts of the square's first block (N1000), one per pass
};

SlopeRun run_slope(const std::string& name, const std::string& extra) {
  const auto dir = temp_dir(name);
  SlopeRun r;
  r.cli = run_nck("run " + mill() + " " + mill() + "/slope.nc --trace " + (dir / "t.csv").string() + " --events " +
                  (dir / "e.jsonl").string() + " " + extra);
  const auto lines = split(read_file(dir / "t.csv"), '\n');
  if (!lines.empty()) r.header = split(lines[0], ',');
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    std::vector<double> row;
    for (const std::string& c : split(lines[i], ',')) row.push_back(std::stod(c));
    r.rows.push_back(std::move(row));
  }
  for (const nlohmann::json& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "block" && !e["n"].is_null() && e["n"].get<long>() == 1000) r.square_t.push_back(e["t"]);
  return r;
}

std::size_t column(const SlopeRun& r, const std::string& name) {
  return static_cast<std::size_t>(std::find(r.header.begin(), r.header.end(), name) - r.header.begin());
}

// The largest |value| of column `col` over the rows with t in [from, to).
double peak(const SlopeRun& r, std::size_t col, double from, double to) {
  double m = 0;
  for (const auto& row : r.rows)
    if (row[0] >= from - 1e-9 && row[0] < to - 1e-9) m = std::max(m, std::fabs(row.at(col)));
  return m;
}

TEST(TraceColumns, DefaultTraceIsUnchanged) {
  const SlopeRun plain = run_slope("tc-plain", "");
  ASSERT_EQ(plain.cli.exit_code, 0) << plain.cli.output;
  EXPECT_EQ(column(plain, "path.a"), plain.header.size());
  const SlopeRun extra = run_slope("tc-extra", "--trace-columns path.a,path.j");
  ASSERT_EQ(extra.cli.exit_code, 0) << extra.cli.output;
  ASSERT_EQ(extra.header.size(), plain.header.size() + 2);
  EXPECT_TRUE(std::equal(plain.header.begin(), plain.header.end(), extra.header.begin()));
  EXPECT_EQ(extra.header[plain.header.size()], "path.a");
  EXPECT_EQ(extra.header[plain.header.size() + 1], "path.j");
  ASSERT_EQ(extra.rows.size(), plain.rows.size());
  for (std::size_t i = 0; i < plain.rows.size(); i += 97)
    EXPECT_TRUE(std::equal(plain.rows[i].begin(), plain.rows[i].end(), extra.rows[i].begin())) << "row " << i;
}

TEST(TraceColumns, TrapezJerkStaysWithinAOverTr) {
  const SlopeRun r = run_slope("tc-jerk", "--trace-columns path.j,path.a");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  ASSERT_EQ(r.square_t.size(), 3u) << "STEP, TRAPEZ, SIN2 passes";
  const std::size_t a = column(r, "path.a"), j = column(r, "path.j");
  ASSERT_LT(j, r.header.size());
  constexpr double kDt = 0.001, kJerk = 2500 / 0.050;
  // TRAPEZ: from its first block (3 cycles for STEP's last step into it) to
  // SIN2's first block.
  const double trapez_j = peak(r, j, r.square_t[1] + 3 * kDt, r.square_t[2]);
  EXPECT_LE(trapez_j, kJerk * (1 + 1e-6));
  EXPECT_GT(trapez_j, 0.5 * kJerk);  // the ramps use the bound
  EXPECT_LE(peak(r, a, r.square_t[1], r.square_t[2]), 2500 * (1 + 1e-9));
  // STEP steps its acceleration within a cycle: a/dt = 2,500,000 mm/s^3.
  EXPECT_GT(peak(r, j, r.square_t[0], r.square_t[1]), 20 * kJerk);
}

// path.v (issue 47): the path velocity, first of each channel's extras
// whatever the list's order; its backward difference is path.a.
TEST(TraceColumns, PathVelocityComesFirst) {
  const SlopeRun r = run_slope("tc-v", "--trace-columns path.a,path.v");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const std::size_t v = column(r, "path.v"), a = column(r, "path.a");
  ASSERT_EQ(v + 1, a);
  ASSERT_EQ(a + 1, r.header.size());
  double top = 0;
  for (std::size_t i = 1; i < r.rows.size(); ++i) {
    top = std::max(top, r.rows[i][v]);
    EXPECT_NEAR((r.rows[i][v] - r.rows[i - 1][v]) / 0.001, r.rows[i][a], 1e-2) << "row " << i;
  }
  EXPECT_GT(top, 0);
}

TEST(TraceColumns, UnknownColumnIsBadUsage) {
  const CliResult c = run_nck("run " + mill() + " " + mill() + "/slope.nc --trace-columns path.x");
  EXPECT_EQ(c.exit_code, 2) << c.output;
  EXPECT_NE(c.output.find("path.x"), std::string::npos) << c.output;
}

}  // namespace
}  // namespace nck::app
