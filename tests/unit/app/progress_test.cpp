// The progress line of `nck run` on a terminal (issue 17, item 9): share of
// the program, the block running, simulated time, real-time factor, ETA;
// cleared before the summary; absent without a terminal or with --no-progress.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

// A program far longer than the wall-clock limit lets the run show its progress.
std::string long_program(const std::filesystem::path& dir) {
  const auto p = dir / "long.nc";
  std::ofstream f(p);
  f << "N1 G01 F100\n";
  for (int i = 0; i < 4000; ++i) f << fmt::format("N{} X{}\n", 10 + i, i % 2 == 0 ? 10 : 0);
  f << "M30\n";
  return p.string();
}

TEST(Progress, OnATerminalItShowsHowFarAndClearsItselfBeforeTheSummary) {
  const auto dir = temp_dir("progress_tty");
  const std::string cmd = std::string(NCK_BINARY) + " run " + root() + "/examples/mill " + long_program(dir) +
                          " --max-wall 1.5";
  // script(1) gives nck a terminal as stderr.
  CliResult r = run_shell("script -qec '" + cmd + "' /dev/null");
  EXPECT_NE(r.output.find("% N"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(" line "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("s simulated, "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("x real time | ETA "), std::string::npos) << r.output;
  // The last thing before each message is the erase of the progress line.
  const std::size_t summary = r.output.find("nck: error 940006");
  ASSERT_NE(summary, std::string::npos) << r.output;
  EXPECT_EQ(r.output.rfind("\r\033[K", summary), summary - 4) << r.output;
}

TEST(Progress, NoProgressWithoutATerminalOrWithTheOption) {
  const auto dir = temp_dir("progress_off");
  const std::string cmd = std::string(NCK_BINARY) + " run " + root() + "/examples/mill " + long_program(dir) +
                          " --max-wall 0.5";
  EXPECT_EQ(run_shell(cmd + " 2>&1").output.find("ETA"), std::string::npos);
  CliResult tty = run_shell("script -qec '" + cmd + " --no-progress' /dev/null");
  EXPECT_NE(tty.output.find("940006"), std::string::npos) << tty.output;
  EXPECT_EQ(tty.output.find("ETA"), std::string::npos) << tty.output;
}

}  // namespace
}  // namespace nck::app::testing
