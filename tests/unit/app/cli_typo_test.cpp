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
      {"zzzzzz", "'zzzzzz' is not one of check, run, parse"},
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
