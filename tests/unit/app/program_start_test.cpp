// Where a file's main program starts, through the nck binary (issue 44,
// item 7; TF5200 diagnosis 20193, main program start): a file whose first
// character outside comments is neither a blank nor '%' is an unnamed main
// program from its first line; %name starts a named one; a % after the
// program end is harmless; a % line inside the main program is 20193.
// Nothing is skipped without a diagnostic.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

struct MillRun {
  CliResult cli;
  json final_state;
};

// `nck run` on the mill with `text` as the program (main.nc).
MillRun run_mill(const std::string& name, const std::string& text) {
  const auto dir = temp_dir("start-" + name);
  write(dir / "main.nc", text);
  MillRun r;
  r.cli = run_nck("run " + mill() + " " + (dir / "main.nc").string() + " --final " + (dir / "f.json").string());
  if (std::filesystem::exists(dir / "f.json")) r.final_state = json::parse(read_file(dir / "f.json"));
  return r;
}

double x_of(const MillRun& r) { return r.final_state["channels"][0]["axes"]["X"]["pcs"].get<double>(); }

// 5 of 44 real CAM files end with % after M30: that program ran nothing
// and ended with "no M30".
TEST(ProgramStart, PercentAfterTheProgramEndIsHarmless) {
  const MillRun r = run_mill("trailing", "N10 G0 X10\nN20 M30\n%\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_EQ(r.cli.output.find("920049"), std::string::npos) << r.cli.output;
  EXPECT_NEAR(x_of(r), 10, 1e-9);
}

TEST(ProgramStart, CommentsBeforeANamedProgramAreNoCode) {
  const MillRun r = run_mill("named", "; header\n(note)\n\n#COMMENT BEGIN\nG0 X99\n#COMMENT END\n%part\nG0 X3\nM30\n%\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_NEAR(x_of(r), 3, 1e-9);
}

// Code before %name starts the unnamed main program: it runs, and the
// header after it is 20193 naming where that program started.
TEST(ProgramStart, HeaderAfterCodeIs20193) {
  const MillRun r = run_mill("code-first", "; comment\nN10 G0 X5\n%main\nG0 X10\nM30\n");
  EXPECT_EQ(r.cli.exit_code, 1) << r.cli.output;
  EXPECT_NE(r.cli.output.find("main.nc:3: error 20193"), std::string::npos) << r.cli.output;
  EXPECT_NE(r.cli.output.find("line 2"), std::string::npos) << r.cli.output;  // where the program started
  EXPECT_NEAR(x_of(r), 5, 1e-9);  // N10 ran: nothing was skipped
}

TEST(ProgramStart, LocalSubroutineInsideTheMainProgramIs20193) {
  const CliResult r = run_nck("parse " + write(temp_dir("start-local") / "main.nc",
                                               "%main\nG0 X1\n%L sub\nG0 X2\nM17\n").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("main.nc:3:1: error 20193"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("%MAIN"), std::string::npos) << r.output;
}

// A file of local subroutines only has no main program: said, not run empty.
TEST(ProgramStart, OnlyLocalSubroutinesIsNoMainProgram) {
  const CliResult r = run_nck("parse " + write(temp_dir("start-none") / "main.nc",
                                               "%L a\nG0 X1\nM17\n%L b\nG0 X2\nM17\n").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("main.nc:1:1: error 920053"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace nck::app
