// Command-line behaviour users expect from the tools they know (issue 17):
// a missing program is bad usage, files from Windows editors are read, and a
// location never says line 0.
#include <gtest/gtest.h>

#include <fmt/format.h>

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
  // The one warning is the mill's sensorless S2 (70252), none of the lists.
  EXPECT_NE(check.output.find("0 error(s), 1 warning(s)"), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("warning 70252"), std::string::npos) << check.output;
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

// A diagnostic at the end of the file names its last line, never one past it.
TEST(InputTolerance, UnclosedStructurePointsAtTheLastLine) {
  const auto dir = temp_dir("unclosed_at_end");
  std::ofstream(dir / "p.nc") << "N10 G01 X10 F100\n$IF 1\nN20 X20\n";
  CliResult r = run_nck("parse " + (dir / "p.nc").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("p.nc:3:1: error 920041"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("p.nc:4"), std::string::npos) << r.output;
}

// Lines after 'Ende' are ignored, with one warning naming the first of them.
TEST(InputTolerance, TextAfterEndeIsAWarning) {
  const auto m = patched_example("mill", "after_ende", "zero.lis", "");
  std::ofstream(m.dir / "zero.lis", std::ios::app) << "# a remark is fine\n\nnp_grp[0].versch[0] 1000\nmore 2\n";
  const std::size_t ende_line = count_lines(read_file(m.dir / "zero.lis")) - 4;
  CliResult check = run_nck("check " + m.dir.string());
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_NE(check.output.find(fmt::format("zero.lis:{}: warning 910030: 'np_grp[0].versch[0] 1000' stands after "
                                          "the Ende line {}",
                                          ende_line + 3, ende_line)),
            std::string::npos)
      << check.output;
  EXPECT_NE(check.output.find("0 error(s), 2 warning(s)"), std::string::npos) << check.output;  // and 70252 (S2)
}

// A relation between two keys is reported in the units the list file uses.
TEST(InputTolerance, RelationErrorsInListUnits) {
  const auto m = patched_example("mill", "relation_units", "x.lis", "getriebe[0].vb_eilgang 900000");
  CliResult check = run_nck("check " + m.dir.string());
  EXPECT_EQ(check.exit_code, 1) << check.output;
  EXPECT_NE(check.output.find("getriebe[0].vb_eilgang (900000 µm/s) must not exceed getriebe[0].dynamik.vb_max "
                              "(500000 µm/s)"),
            std::string::npos)
      << check.output;
  const auto s = patched_example("mill", "relation_units_deg", "s1.lis", "getriebe[0].vb_eilgang 80000000");
  check = run_nck("check " + s.dir.string());
  EXPECT_NE(check.output.find("getriebe[0].vb_eilgang (80000000 × 0.001°/s) must not exceed getriebe[0].dynamik.vb_max "
                              "(72000000 × 0.001°/s)"),
            std::string::npos)
      << check.output;
}

// Number options say what is wrong in words: the range, not a number, not whole.
TEST(InputTolerance, NumberOptionsExplainWhatIsWrong) {
  const std::string run = "run " + root() + "/examples/mill " + root() + "/examples/mill/contour.nc ";
  struct Case {
    std::string args, message;
  } cases[] = {
      {run + "--trace-every 0", "--trace-every: must be ≥ 1, not 0"},
      {run + "--trace-every abc", "--trace-every: 'abc' is not a number"},
      {run + "--trace-every 2.5", "--trace-every: '2.5' is not a whole number"},
      {run + "--trace-every 99999999999999999999999", "'99999999999999999999999' is too large (at most 4294967295)"},
      {run + "--max-time -1", "--max-time: must be ≥ 0.001, not -1"},
      {run + "--max-wall nan", "--max-wall: 'nan' is not a number"},
      {"parse x.nc --channel 0", "--channel: must be ≥ 1, not 0"},
  };
  for (const Case& c : cases) {
    CliResult r = run_nck(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_NE(r.output.find("940001"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_EQ(r.output.find("179769313486231570814527423731704356798070567525844996598917476803157"), std::string::npos);
  }
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

namespace nck::app::testing {
namespace {

// h:mm:ss.mmm, computed here independently of the app.
std::string clock_text(double s) {
  const long ms = std::lround(s * 1000);
  return fmt::format("{}:{:02}:{:02}.{:03}", ms / 3600000, ms / 60000 % 60, ms / 1000 % 60, ms % 1000);
}

// The last line on stderr sums the run up: end reason, cycle time, blocks,
// errors, warnings and the time spent waiting per reason, all consistent
// with the events file.
TEST(EndOfRunSummary, LastLineAgreesWithTheEvents) {
  const auto dir = temp_dir("summary");
  const std::string ex = root() + "/examples/mill";
  CliResult r = run_nck_raw("run " + ex + " " + ex + "/spindle.nc --plc " + ex + "/spindle.plc --events " +
                            (dir / "e.jsonl").string() + " --final " + (dir / "f.json").string() + " 2>&1 >/dev/null");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto lines = split(r.output, '\n');
  ASSERT_FALSE(lines.empty());
  const std::string& last = lines.back();
  std::size_t blocks = 0;
  double waited_ack = 0;
  std::map<std::string, double> since;
  for (const auto& e : read_jsonl(dir / "e.jsonl")) {
    blocks += e["ev"] == "block";
    const std::string key = e.value("reason", "") + e.value("fn", "") + e.value("spindle", nlohmann::json()).dump();
    if (e["ev"] == "wait") since[key] = e["t"].get<double>();
    if (e["ev"] == "wait_end" && e["reason"] == "plc_ack") waited_ack += e["t"].get<double>() - since[key];
  }
  const double end_s = nlohmann::json::parse(read_file(dir / "f.json"))["time"].get<double>();
  EXPECT_NE(last.find(fmt::format("program_end after {} simulated", clock_text(end_s))), std::string::npos) << last;
  EXPECT_NE(last.find(fmt::format("; {} block(s), 0 error(s), 0 warning(s)", blocks)), std::string::npos) << last;
  EXPECT_NE(last.find(fmt::format("plc_ack {:.3f} s", waited_ack)), std::string::npos) << last;
}

}  // namespace
}  // namespace nck::app::testing
