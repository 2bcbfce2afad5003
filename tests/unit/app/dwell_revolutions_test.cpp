// G4 S.. (docs/nc-language.md): a dwell of main-spindle revolutions, counted from the
// spindle's set-point speed each cycle, through `nck run` on the mill.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

TEST(DwellRevolutions, LastsAsManyTurnsAsTheSpindleMakes) {
  const auto dir = temp_dir("dwell-revs");
  // 600 rpm = 10 turns/s: G4 S10 lasts 1 s once the speed is reached; M5 after it.
  std::ofstream(dir / "p.nc") << "N10 M3 S600\nN20 G4 S10\nN30 M5\nN40 M30\n";
  CliResult r = run_nck("run " + root() + "/examples/mill " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string() + " --trace " + (dir / "t.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  double t20 = -1, t30 = -1;
  for (const json& e : read_jsonl(dir / "e.jsonl")) {
    if (e["ev"] == "block" && e["n"] == 20) t20 = e["t"];
    if (e["ev"] == "block" && e["n"] == 30) t30 = e["t"];
  }
  ASSERT_GE(t20, 0);
  ASSERT_GT(t30, t20);
  // The turns of S1 between the two block starts, from the trace.
  const auto lines = split(read_file(dir / "t.csv"), '\n');
  const auto head = split(lines[0], ',');
  const auto col = std::find(head.begin(), head.end(), "S1.rpm") - head.begin();
  double turns = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto c = split(lines[i], ',');
    if (c.size() <= static_cast<std::size_t>(col)) continue;
    const double t = std::stod(c[0]);
    if (t >= t20 - 1e-9 && t < t30 - 1e-9) turns += std::fabs(std::stod(c[col])) / 60.0 * 0.001;
  }
  EXPECT_NEAR(turns, 10.0, 600.0 / 60.0 * 0.001 * 1.5);  // within one cycle of turning
}

TEST(DwellRevolutions, StandingSpindleIsError930042) {
  const auto dir = temp_dir("dwell-revs-stop");
  std::ofstream(dir / "p.nc") << "N10 G4 S5\nN20 M30\n";
  CliResult r = run_nck("run " + root() + "/examples/mill " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  int errors = 0;
  for (const json& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "error") {
      ++errors;
      EXPECT_EQ(e["id"], 930042);
      EXPECT_EQ(e["line"], 1);
    }
  EXPECT_EQ(errors, 1);
}

}  // namespace
}  // namespace nck::app
