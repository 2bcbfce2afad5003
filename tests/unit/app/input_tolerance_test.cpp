// Command-line behaviour users expect from the tools they know (issue 17):
// a missing program is bad usage, files from Windows editors are read, and a
// location never says line 0.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

TEST(InputTolerance, AMissingProgramIsBadUsageExit2) {
  const auto dir = temp_dir("missing_program");
  const std::string missing = (dir / "nope.nc").string();
  CliResult run = run_nck("run " + root() + "/examples/mill " + missing);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("940001"), std::string::npos);
  EXPECT_EQ(run_nck("parse " + missing).exit_code, 2);
}

TEST(InputTolerance, ByteOrderMarkAndCrlfInProgramsAndLists) {
  const auto m = patched_example("mill", "bom_crlf", "zero.lis", "");
  const std::string zero = read_file(m.dir / "zero.lis");
  std::string crlf;
  for (char c : zero) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  std::ofstream(m.dir / "zero.lis", std::ios::binary) << "\xEF\xBB\xBF" << crlf;
  std::ofstream(m.dir / "p.nc", std::ios::binary) << "\xEF\xBB\xBFN10 G0 X1\r\nM30\r\n";
  CliResult check = run_nck("check " + m.dir.string());
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_NE(check.output.find("0 error(s), 0 warning(s)"), std::string::npos) << check.output;
  CliResult run = run_nck("run " + m.dir.string() + " " + (m.dir / "p.nc").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
}

// The program-end error points at the program's last block, not at line 0.
TEST(InputTolerance, MissingProgramEndPointsAtTheLastLine) {
  const auto dir = temp_dir("no_m30");
  std::ofstream(dir / "p.nc") << "N10 G0 X1\nN20 G0 X2\n";
  CliResult r = run_nck("run " + root() + "/examples/mill " + (dir / "p.nc").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("p.nc:2: error 930007"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find(":0:"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace nck::app::testing

namespace nck::app::testing {
namespace {

// `nck errors ID` and `nck params KEY` show the matching entries only.
TEST(Lookups, OneErrorIdAndTheKeysOfAName) {
  CliResult e = run_nck_raw("errors 930001");
  EXPECT_EQ(e.exit_code, 0);
  EXPECT_EQ(count_lines(e.output), 3u) << e.output;  // header, separator, the entry
  EXPECT_NE(e.output.find("| 930001 | error | KernelNotYetSupported"), std::string::npos);
  CliResult p = run_nck_raw("params getriebe[i].dynamik.vb_max");
  EXPECT_EQ(p.exit_code, 0);
  EXPECT_EQ(count_lines(p.output), 3u) << p.output;
  EXPECT_NE(p.output.find("P-AXIS-00212"), std::string::npos);
  EXPECT_EQ(run_nck("params no_such_key").exit_code, 1);
}

}  // namespace
}  // namespace nck::app::testing
