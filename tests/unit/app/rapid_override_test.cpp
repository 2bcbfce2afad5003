// The rapid override (P-CHAN-00181 g00_override_mode) from the command line:
// a G0 of 300 mm on X (rapid 500 mm/s, a_grenz 3000 mm/s^2) takes
// 300/v + v/3000 s at the speed the mode's override leaves it, and the feed
// override keeps acting on G1 in every mode.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "time_by_cause_helpers.hpp"

namespace nck::app::testing {
namespace {

// The mill with g00_override_mode set to `mode`.
std::string mill_with_rapid_mode(const std::string& mode) {
  namespace fs = std::filesystem;
  const auto dir = temp_dir("rapid_mode_" + mode);
  fs::copy(mill(), dir / "m", fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  std::ifstream in(dir / "m" / "channel1.lis");
  std::string text, line;
  while (std::getline(in, line)) {
    if (line.starts_with("g00_override_mode")) continue;
    if (line.starts_with("Ende")) text += "g00_override_mode " + mode + "\n";  // keys after it are ignored
    text += line + "\n";
  }
  in.close();
  write(dir / "m" / "channel1.lis", text);
  return (dir / "m").string();
}

// The time of line 2 (the G0) and line 3 (G1 X0 at F6000, 100 mm/s) of one run.
std::pair<double, double> g0_and_g1_s(const std::string& mode, double feed_pct, double rapid_pct) {
  const std::string plc = fmt::format("0 feed_override {}\n0 rapid_override {}\n", feed_pct, rapid_pct);
  const CauseRun r = run_program("rapid_" + mode, "G90 G1 X0 Y0 Z0 F6000\nG0 X300\nG1 X0\nM30\n", plc,
                                 mill_with_rapid_mode(mode));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return {block_of(r.final, 2).value("time_s", 0.0), block_of(r.final, 3).value("time_s", 0.0)};
}

// 300 mm at the rapid speed (500 mm/s) times `factor`, with a ramp up and down at 3000 mm/s^2.
double g0_s(double factor) {
  const double v_mm_s = 500 * factor;
  return 300 / v_mm_s + v_mm_s / 3000;
}

constexpr double kCycleTolerance_s = 0.004;

TEST(RapidOverride, NotUsedLetsTheFeedOverrideActOnG0) {
  const auto [g0, g1] = g0_and_g1_s("NOT_USED", 50, 25);
  EXPECT_NEAR(g0, g0_s(0.5), kCycleTolerance_s);
  EXPECT_NEAR(g1, 300 / 50.0 + 50.0 / 2500, kCycleTolerance_s);
}

TEST(RapidOverride, MinimumOfG0G1TakesTheSmallerOverride) {
  EXPECT_NEAR(g0_and_g1_s("MINIMUM_OF_G0_G1", 50, 25).first, g0_s(0.25), kCycleTolerance_s);
  EXPECT_NEAR(g0_and_g1_s("1", 25, 50).first, g0_s(0.25), kCycleTolerance_s);  // the number spells it too
}

TEST(RapidOverride, ActiveTakesTheRapidOverrideOnlyAndTheFeedOverrideStaysOnG1) {
  const auto [g0, g1] = g0_and_g1_s("ACTIVE", 50, 100);
  EXPECT_NEAR(g0, g0_s(1.0), kCycleTolerance_s);
  EXPECT_NEAR(g1, 300 / 50.0 + 50.0 / 2500, kCycleTolerance_s);
}

TEST(RapidOverride, AnUnknownModeIsRefusedWithItsLine) {
  const CauseRun r = run_program("rapid_bad", "G0 X1\nM30\n", {}, mill_with_rapid_mode("FAST"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("channel1.lis"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("g00_override_mode"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace nck::app::testing
