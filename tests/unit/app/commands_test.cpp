#include <gtest/gtest.h>

#include <algorithm>

#include "cli_helpers.hpp"
#include "nck/core/diagnostic.hpp"

namespace nck::app {
namespace {

using namespace testing;

TEST(CheckCommand, ExamplesAreClean) {
  for (const char* m : {"mill", "lathe", "two-channel"}) {
    CliResult r = run_nck("check " + root() + "/examples/" + m);
    EXPECT_EQ(r.exit_code, 0) << m << "\n" << r.output;
  }
}

TEST(CheckCommand, MissingFolderIsAnError) {
  CliResult r = run_nck("check /nonexistent/machine");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("910001"), std::string::npos) << r.output;
}

TEST(ParseCommand, GarbageExitsNonZeroWithADiagnostic) {
  const auto dir = temp_dir("garbage");
  const auto p = dir / "garbage.nc";
  {
    std::ofstream f(p, std::ios::binary);
    for (int i = 0; i < 4096; ++i) f.put(static_cast<char>((i * 7919) % 256));
  }
  CliResult r = run_nck("parse " + p.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("garbage.nc:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("error"), std::string::npos);
}

// An error met again in a loop is listed once, and the errors after the
// loop are still found (lint mode goes on without a new diagnostic).
TEST(ParseCommand, GoesOnAfterAnErrorRepeatedInALoop) {
  const auto p = write(temp_dir("lint_loop") / "p.nc", "G0 X0\n$FOR P1 = 1, 3, 1\nG444\n$ENDFOR\nG555\nM30\n");
  CliResult r = run_nck("parse " + p.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("p.nc:3:1: error 920005"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("p.nc:5:1: error 920005"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("2 error(s)"), std::string::npos) << r.output;
}

TEST(ParseCommand, JsonPrintsOneObjectPerBlock) {
  CliResult r = run_nck("parse --json --machine " + root() + "/examples/lathe " + root() + "/examples/lathe/turn.nc");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::size_t objects = 0;
  for (const std::string& line : split(r.output, '\n'))
    if (!line.empty() && line[0] == '{') {
      EXPECT_TRUE(nlohmann::json::accept(line)) << line;
      ++objects;
    }
  EXPECT_EQ(objects, 12u);
}

TEST(Docs, ErrorsMarkdownIsUpToDate) {
  EXPECT_EQ(read_file(root() + "/docs/errors.md"), errors_markdown())
      << "regenerate with: nck errors > docs/errors.md";
}

TEST(Docs, ParametersMarkdownIsUpToDate) {
  CliResult r = run_nck("params");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(read_file(root() + "/docs/parameters.md"), r.output)
      << "regenerate with: nck params > docs/parameters.md";
}

TEST(CheckCommand, ReportsPlausibilityErrorAtFileAndLine) {
  const auto [dir, line] = patched_example("mill", "check_err", "x.lis", "kenngr.ref_ohne_nocken 1");
  CliResult r = run_nck("check " + dir.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("x.lis:" + std::to_string(line) + ": error 910018:"), std::string::npos)
      << r.output;
}

TEST(CheckCommand, WarningsAloneExitZero) {
  const auto [dir, line] = patched_example("mill", "check_warn", "x.lis", "getriebe[0].wegaufz 0");
  CliResult r = run_nck("check " + dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("x.lis:" + std::to_string(line) + ": warning 110386:"), std::string::npos)
      << r.output;
}

TEST(CheckCommand, UnknownKeyNamesTheNearestKnownKey) {
  const auto [dir, line] = patched_example("mill", "check_unknown", "x.lis", "getriebe[0].dynamik.vb_max_cmd 1000");
  CliResult r = run_nck("check " + dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("x.lis:" + std::to_string(line) + ": warning 910002"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("vb_max"), std::string::npos) << r.output;
}

TEST(ParseCommand, OverlongLineIsADiagnosticNotACrash) {
  const auto dir = temp_dir("longline");
  const auto p = dir / "long.nc";
  std::ofstream(p) << "%long\nN10 G1 X" << std::string(100000, '1') << " F100\nN20 M30\n";
  CliResult r = run_nck("parse " + p.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("long.nc:2"), std::string::npos) << r.output.substr(0, 500);
}

TEST(ParseCommand, MissingFileIsADiagnostic) {
  CliResult r = run_nck("parse /nonexistent/prog.nc");
  EXPECT_EQ(r.exit_code, 2);  // bad usage (README: exit 2), not an error in a program
  EXPECT_NE(r.output.find("prog.nc"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace nck::app
