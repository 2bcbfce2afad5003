// $GOTO through `nck run` on the mill: which numbered blocks execute in
// which order (block events) and where the axes are when they start (trace),
// plus each $GOTO error with its ID and line.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

struct Started {
  long n = 0;
  std::array<double, 3> xyz{};  // X Y Z set points when the block starts
};

// Every numbered block event in order (a block run twice appears twice).
std::vector<Started> started_blocks(const std::filesystem::path& dir) {
  std::map<long, std::array<double, 3>> by_ms;
  const auto lines = split(read_file(dir / "t.csv"), '\n');
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto c = split(lines[i], ',');
    by_ms[std::lround(std::stod(c[0]) * 1000)] = {std::stod(c[1]), std::stod(c[2]), std::stod(c[3])};
  }
  std::vector<Started> out;
  for (const json& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "block" && !e["n"].is_null()) {
      const long ms = std::lround(e["t"].get<double>() * 1000);
      out.push_back({e["n"].get<long>(), ms == 0 ? std::array<double, 3>{} : by_ms.at(ms - 1)});
    }
  return out;
}

TEST(GotoRun, ForwardBackwardAndIfGotoOnTheMill) {
  const auto dir = temp_dir("goto-mill");
  CliResult r = run_example("mill", "jumps.nc", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto b = started_blocks(dir);
  std::vector<long> ns;
  for (const auto& s : b) ns.push_back(s.n);
  // N40 and N110 are jumped over; N70 runs once per pass of the V.L.PASS loop
  // (N30, N60, N80-N100 are jumps and assignments: no block of their own).
  EXPECT_EQ(ns, (std::vector<long>{10, 20, 50, 70, 70, 70, 120, 130, 140})) << ::testing::PrintToString(ns);
  // Where the axes are when each block starts: pass k of N70 starts where
  // pass k-1 left Y (5 mm per pass); N120 starts after the third pass at Y15.
  std::vector<double> y_at_70;
  for (const auto& s : b) {
    if (s.n == 70) y_at_70.push_back(s.xyz[1]);
    if (s.n == 120) {
      EXPECT_NEAR(s.xyz[0], 10.0, 1e-6);
      EXPECT_NEAR(s.xyz[1], 15.0, 1e-6);
      EXPECT_NEAR(s.xyz[2], 10.0, 1e-6);
    }
    if (s.n == 130) {
      EXPECT_NEAR(s.xyz[0], 20.0, 1e-6);
    }
  }
  // The passes join at speed (same direction, continuous path): the next one
  // starts within one cycle's travel at F1000 (16.7 mm/s * 1 ms) of the end.
  const double step_mm = 1000.0 / 60.0 * 0.001;
  ASSERT_EQ(y_at_70.size(), 3u);
  EXPECT_NEAR(y_at_70[0], 0.0, 1e-6);
  EXPECT_NEAR(y_at_70[1], 5.0, step_mm);
  EXPECT_NEAR(y_at_70[2], 10.0, step_mm);
  // The skipped blocks never move X to 99 or Z to 99.
  const auto lines = split(read_file(dir / "t.csv"), '\n');
  double max_x = -1e9, max_z = -1e9;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto c = split(lines[i], ',');
    max_x = std::max(max_x, std::stod(c[1]));
    max_z = std::max(max_z, std::stod(c[3]));
  }
  EXPECT_NEAR(max_x, 20.0, 1e-6);
  EXPECT_NEAR(max_z, 10.0, 1e-6);
}

// Runs `program` on the mill; the error events as (id, line).
std::vector<std::pair<int, int>> errors_of(const std::string& name, const std::string& program, CliResult& r) {
  const auto dir = temp_dir(name);
  std::ofstream(dir / "p.nc") << program;
  r = run_nck("run " + root() + "/examples/mill " + (dir / "p.nc").string() + " --events " +
              (dir / "e.jsonl").string());
  std::vector<std::pair<int, int>> out;
  for (const json& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "error") out.emplace_back(e["id"].get<int>(), e["line"].get<int>());
  return out;
}

TEST(GotoRun, UnknownLabelIs920051WithItsLine) {
  CliResult r;
  auto e = errors_of("goto-unknown", "N10 G0 X1\nN20 $GOTO N99\nN30 M30\n", r);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  ASSERT_EQ(e.size(), 1u) << r.output;
  EXPECT_EQ(e[0], (std::pair<int, int>{920051, 2}));
  EXPECT_NE(r.output.find("N99"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("p.nc"), std::string::npos) << r.output;
}

TEST(GotoRun, JumpErrorsCarryTheirIds) {
  CliResult r;
  // into a $WHILE body from outside
  EXPECT_EQ(errors_of("goto-into", "N10 $GOTO N30\nN20 $WHILE 1\nN30: G0 X1\nN40 $ENDWHILE\nN50 M30\n", r),
            (std::vector<std::pair<int, int>>{{920101, 1}}))
      << r.output;
  // inside a $FOR body to a label of the same body
  EXPECT_EQ(errors_of("goto-in", "N10 $FOR P1 = 1, 3\nN20 $GOTO N40\nN30 G0 X1\nN40: G0 X2\nN50 $ENDFOR\nN60 M30\n", r),
            (std::vector<std::pair<int, int>>{{920102, 2}}))
      << r.output;
  // no N / [ after $GOTO
  EXPECT_EQ(errors_of("goto-syntax", "N10 G0 X1\nN20 G0 X2\nN30 $GOTO 10\nN40 M30\n", r),
            (std::vector<std::pair<int, int>>{{920100, 3}}))
      << r.output;
  // a label of a local subroutine is out of the main program's reach
  EXPECT_EQ(errors_of("goto-level", "%L SUB\nN70: G0 X7\nN80 M17\n%MAIN\nN10 LL SUB\nN20 $GOTO N70\nN30 M30\n", r),
            (std::vector<std::pair<int, int>>{{920051, 6}}))
      << r.output;
}

TEST(GotoRun, EndlessJumpLoopEndsWithTheLoopBudget920042) {
  // No motion in the loop: the decoder alone spins; the run-wide budget of
  // 10,000,000 loop iterations (backward jumps count) ends it (about 4 s).
  CliResult r;
  auto e = errors_of("goto-endless", "N5 G0 X1\nP1 = 0\nN10: P1 = P1 + 1\nN20 $GOTO N10\nN30 M30\n", r);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(e, (std::vector<std::pair<int, int>>{{920042, 4}})) << r.output;
}

}  // namespace
}  // namespace nck::app
