// Time lost against the ideal knows spindle-bound feeds (issue 48 item 2):
// under G95, G33 and G96 the ideal time takes the feed those modes command
// (programmed spindle speed x mm/rev), not length / the axes' maximum; a
// block run exactly as programmed loses (almost) nothing, and the cause
// table still adds up to the cycle time.
#include <gtest/gtest.h>

#include <numbers>

#include "time_by_cause_helpers.hpp"

namespace nck::app::testing {
namespace {

using nlohmann::json;

std::string lathe() { return root() + "/examples/lathe"; }

// channel 1's block of main-program line `line` (failing the test when missing)
json block_at(const CauseRun& r, std::uint32_t line) {
  const json b = block_of(r.final, line);
  EXPECT_FALSE(b.empty()) << "no block at line " << line;
  return b;
}

// An example of the lathe, run with --final.
CauseRun run_lathe_example(const std::string& program) {
  const auto dir = temp_dir("ideal_" + program);
  const std::string final_path = (dir / "final.json").string();
  const CliResult r = run_nck("run " + lathe() + " " + lathe() + "/" + program + " --final " + final_path);
  CauseRun out{r.exit_code, json::object(), r.output};
  std::ifstream f(final_path);
  if (f) out.final = json::parse(f, nullptr, false);
  return out;
}

// The classes add up to the channel's time (whole cycles: exactly but for
// the sum's rounding).
void expect_causes_add_up(const CauseRun& r) {
  const json& ch = r.final["time_by_cause"]["channels"][0];
  double sum_s = 0;
  for (const json& c : ch["causes"]) sum_s += c["time_s"].get<double>();
  EXPECT_NEAR(sum_s, ch["time_s"].get<double>(), 1e-9) << ch["causes"].dump(1);
  EXPECT_NEAR(ch["time_s"].get<double>(), r.final["time"].get<double>(), 1e-9);
}

// profile.nc: G95 F0.2 at 800 rpm is 160 mm/min, and the blocks run at it.
// N50 G1 Z-20 from Z2 is 22 mm: 8.25 s at the feed; it lost 8.206 s against
// 22 mm / the axes' maximum before. What is left is its ramp from rest
// (a few ms at the feed acceleration).
TEST(TimeByCauseIdeal, FeedPerRevolutionLosesNothingAtItsFeed) {
  const CauseRun r = run_lathe_example("profile.nc");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json n50 = block_at(r, 8);
  ASSERT_EQ(n50["n"], 50) << n50.dump(1);
  EXPECT_NEAR(n50["ideal_s"].get<double>(), 22.0 / (800 * 0.2 / 60), 1e-3) << n50.dump(1);
  EXPECT_NEAR(n50["lost_s"].get<double>(), 0, 0.02) << n50.dump(1);
  for (const std::uint32_t line : {9u, 10u, 11u}) {  // N60 (the radius), N70, N80: at the feed too
    const json b = block_at(r, line);
    EXPECT_GT(b["ideal_s"].get<double>(), 1.0) << b.dump(1);
    EXPECT_NEAR(b["lost_s"].get<double>(), 0, 0.02) << b.dump(1);
  }
  // the blocks that lose most are now the waits, not the cuts
  const json& top = r.final["time_by_cause"]["channels"][0]["blocks"][0];
  EXPECT_TRUE(top["ideal_s"] == 0) << top.dump(1);
  expect_causes_add_up(r);
}

// thread.nc: G33 K2 at 400 rpm is 800 mm/min, 35 mm a pass: 2.625 s. A pass
// waits for the zero mark (at most a turn, 0.15 s) and ramps; before, each
// lost 2.6 s against 35 mm / the axes' maximum.
TEST(TimeByCauseIdeal, ThreadLosesAtMostTheWaitForItsStartAngle) {
  const CauseRun r = run_lathe_example("thread.nc");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const std::uint32_t line : {9u, 13u, 17u}) {  // N50, N90, N130
    const json b = block_at(r, line);
    EXPECT_NEAR(b["ideal_s"].get<double>(), 35.0 / (400 * 2.0 / 60), 1e-3) << b.dump(1);
    EXPECT_GT(b["lost_s"].get<double>(), -0.01) << b.dump(1);
    EXPECT_LT(b["lost_s"].get<double>(), 60.0 / 400 + 0.02) << b.dump(1);
  }
  expect_causes_add_up(r);
}

// G95 under G96: the feed follows the speed the law commands, n = 1000 v /
// (2 pi r) up to G196's 2000 rpm. N70 faces X40 -> X20 at 0.2 mm/rev:
// ideal = the integral of dr / (F n(r) / 60).
TEST(TimeByCauseIdeal, ConstantCuttingSpeedFeedsPerRevolutionOfTheLaw) {
  const CauseRun r = run_program("css_g95",
                                 "N10 G18 G90\n"
                                 "N20 G196 S2000\n"
                                 "N30 M3 S1000\n"
                                 "N40 G0 X40 Z2\n"
                                 "N50 G96 S150\n"
                                 "N60 G95 F0.2 G1 Z0\n"
                                 "N70 G1 X20\n"
                                 "N80 G94 G0 Z2\n"
                                 "N90 M5\n"
                                 "N100 M30\n",
                                 "", lathe());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json n70 = block_at(r, 7);
  // n(r) = 150000 / (2 pi r) rpm, so dt = dr 2 pi r / (0.2 x 150000) x 60
  const double ideal_s = 60 * std::numbers::pi * (40.0 * 40.0 - 20.0 * 20.0) / (0.2 * 150000);
  EXPECT_NEAR(n70["ideal_s"].get<double>(), ideal_s, 0.01 * ideal_s) << n70.dump(1);
  EXPECT_NEAR(n70["lost_s"].get<double>(), 0, 0.05) << n70.dump(1);
  expect_causes_add_up(r);
}

}  // namespace
}  // namespace nck::app::testing
