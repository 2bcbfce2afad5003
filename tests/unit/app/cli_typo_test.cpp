// Mistyped subcommands and options get a did-you-mean hint (exit 2, 940001).
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;

TEST(CliTypos, MistypedWordsNameTheNearestOne) {
  struct Case {
    std::string args, hint;
  } cases[] = {
      {"rnu a b", "'rnu' is not one (did you mean 'run'?)"},
      {"chek", "did you mean 'check'?"},
      {"run " + root() + "/examples/mill " + root() + "/examples/mill/contour.nc --trce t.csv",
       "--trce (did you mean '--trace'?)"},
      {"run a b --max-tme=3", "(did you mean '--max-time'?)"},
      {"zzzzzz", "'zzzzzz' is not one of check, run, diff, parse, fit-curve, init, serve, params, errors"},
      {"run " + root() + "/examples/mill " + root() + "/examples/mill/contour.nc -report r.html",
       "(did you mean '--report'?)"},
  };
  for (const Case& c : cases) {
    CliResult r = run_nck(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_NE(r.output.find("940001"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.hint), std::string::npos) << c.args << "\n" << r.output;
  }
}

// A long option written with one dash is named with two, whichever
// command it belongs to (issue 31).
TEST(CliTypos, OneDashLongOptionsNameTheTwoDashOption) {
  struct Case {
    std::string args, hint;
  } cases[] = {
      {"-report r.html", "(did you mean '--report'? It is an option of 'nck run')"},
      {"check " + root() + "/examples/mill -report r.html", "(did you mean '--report'? It is an option of 'nck run')"},
      {"check " + root() + "/examples/mill -json", "(did you mean '--json'?)"},
      {"parse -json p.nc", "(did you mean '--json'?)"},
      {"run " + root() + "/examples/mill " + root() + "/examples/mill/contour.nc -events=e.jsonl",
       "(did you mean '--events'?)"},
  };
  for (const Case& c : cases) {
    CliResult r = run_nck(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_NE(r.output.find("error 940001"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.hint), std::string::npos) << c.args << "\n" << r.output;
  }
}

// `nck errors WORD` also searches the causes and remedies, case-insensitive:
// a user knows what went wrong before knowing its name.
TEST(CliTypos, ErrorsFindsAnIdByAWordOfItsDescription) {
  CliResult r = run_nck("errors 'SOFTWARE LIMIT'");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("| 930003 | error | KernelSoftwareLimit |"), std::string::npos) << r.output;
  CliResult remedy = run_nck("errors swe_neg");
  EXPECT_NE(remedy.output.find("| 930003 |"), std::string::npos) << remedy.output;
  EXPECT_NE(run_nck("errors --help").output.find("cause or remedy contains WORD"), std::string::npos);
}

// `-` for stdout and --cycles are in `nck run --help` and in the README.
TEST(CliTypos, StdoutDashAndCyclesAreDocumented) {
  const std::string help = run_nck("run --help").output;
  EXPECT_NE(help.find("FILE - writes that output to stdout"), std::string::npos) << help;
  for (const char* option : {"--events", "--trace", "--final", "--report"})
    EXPECT_NE(help.find(std::string(option) + " FILE"), std::string::npos) << option << "\n" << help;
  EXPECT_NE(help.find("--cycles"), std::string::npos) << help;
  const std::string readme = read_file(root() + "/README.md");
  EXPECT_NE(readme.find("FILE \"-\" below: that output goes to stdout"), std::string::npos);
  EXPECT_NE(readme.find("--cycles DIR"), std::string::npos);
  EXPECT_NE(readme.find("nck check MACHINE [PROGRAM ...]"), std::string::npos);
}

// `nck errors` finds an ID by its number or by (part of) its name.
TEST(CliTypos, ErrorsFindsAnIdByNumberOrName) {
  for (const char* lookup : {"940004", "OutputPathConflict", "outputpath"}) {
    CliResult r = run_nck(std::string("errors ") + lookup);
    EXPECT_EQ(r.exit_code, 0) << lookup << "\n" << r.output;
    EXPECT_NE(r.output.find("| 940004 | error | AppOutputPathConflict |"), std::string::npos) << r.output;
  }
  CliResult none = run_nck("errors NoSuchNameAnywhere");
  EXPECT_EQ(none.exit_code, 1) << none.output;
}

}  // namespace
}  // namespace nck::app
