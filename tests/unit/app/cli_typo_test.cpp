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
  };
  for (const Case& c : cases) {
    CliResult r = run_nck(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_NE(r.output.find("940001"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.hint), std::string::npos) << c.args << "\n" << r.output;
  }
}

}  // namespace
}  // namespace nck::app
