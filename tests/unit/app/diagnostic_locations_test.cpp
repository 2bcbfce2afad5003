// "No location printed twice" (issue 17, point 11): every diagnostic path of
// the binary — run, check, parse; errors in the main program, in nested and
// recursive subroutines (the "called from" chain), from the planner, at the
// end of a file, in a list file, in a PLC scenario, on the command line — is
// run on a bad input, and no stderr line names the same file and line twice
// or says line 0.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <regex>
#include <set>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

// Every "NAME:LINE" and "NAME line LINE" in one line of output, for the
// file names the test uses (subroutines have no extension).
std::vector<std::string> locations(const std::string& line, const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const std::string& n : names) {
    const std::regex re("(^|[/ ])" + n + "(:| line )([0-9]+)");
    for (auto it = std::sregex_iterator(line.begin(), line.end(), re); it != std::sregex_iterator(); ++it)
      out.push_back(n + ":" + (*it)[3].str());
  }
  return out;
}

void expect_each_location_once(const CliResult& r, const std::string& what, const std::vector<std::string>& names) {
  EXPECT_FALSE(r.output.empty()) << what;
  for (const std::string& line : split(r.output, '\n')) {
    EXPECT_EQ(line.find(":0:"), std::string::npos) << what << ": " << line;
    EXPECT_EQ(line.find(" line 0"), std::string::npos) << what << ": " << line;
    std::set<std::string> seen;
    for (const std::string& loc : locations(line, names))
      EXPECT_TRUE(seen.insert(loc).second) << what << ": " << loc << " twice in: " << line;
  }
}

TEST(DiagnosticLocations, NoLocationTwiceAndNoLineZeroOnAnyPath) {
  const auto dir = temp_dir("diag_locations");
  auto write = [&](const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; };
  write("main_bad.nc", "N10 G1 X10 F600\nN20 G1 X\nM30\n");
  write("sub_bad", "N10 G1 X10 F600\nN20 G1 Y\nM17\n");
  write("sub_mid", "N10 L sub_bad\nM17\n");
  write("nested.nc", "N5 G0 X0\nN10 L sub_mid\nM30\n");
  write("sub_self", "N10 L sub_self\nM17\n");
  write("recursive.nc", "N10 L sub_self\nM30\n");
  write("limit.nc", "N10 G0 X99999\nM30\n");
  write("sub_limit", "N10 G0 X99999\nM17\n");
  write("sub_limit.nc", "N10 L sub_limit\nM30\n");
  write("no_end.nc", "N10 G0 X1\nN20 G0 X2\n");
  write("unclosed.nc", "N10 G1 X10 F600\n$IF 1\nN20 X20\n");
  write("no_sub.nc", "N10 L sub_missing\nM30\n");
  write("bad.plc", "0.5 override S9 50\nabc\n1.0 feedhold maybe\n");
  const std::vector<std::string> names = {"main_bad.nc", "sub_bad", "sub_mid", "nested.nc", "sub_self",
                                          "recursive.nc", "limit.nc", "sub_limit", "sub_limit.nc", "no_end.nc",
                                          "unclosed.nc", "no_sub.nc", "bad.plc", "x.lis", "tools.lis", "zero.lis",
                                          "contour.nc"};
  const std::string mill = root() + "/examples/mill";
  auto p = [&](const std::string& n) { return (dir / n).string(); };
  for (const char* prog : {"main_bad.nc", "nested.nc", "recursive.nc", "limit.nc", "sub_limit.nc", "no_end.nc",
                           "unclosed.nc", "no_sub.nc"}) {
    const CliResult run = run_nck("run " + mill + " " + p(prog) + " --no-progress");
    EXPECT_EQ(run.exit_code, 1) << prog << ": " << run.output;
    expect_each_location_once(run, std::string("run ") + prog, names);
    expect_each_location_once(run_nck("parse " + p(prog)), std::string("parse ") + prog, names);
  }
  // the recursion names its calling line once, with a count
  const CliResult rec = run_nck("run " + mill + " " + p("recursive.nc") + " --no-progress");
  EXPECT_NE(rec.output.find("sub_self:1: error 920045"), std::string::npos) << rec.output;
  EXPECT_NE(rec.output.find("called from the same line 19 time(s), called from "), std::string::npos) << rec.output;
  // the nested chain, innermost caller first
  const CliResult nested = run_nck("run " + mill + " " + p("nested.nc") + " --no-progress");
  EXPECT_NE(nested.output.find("sub_bad:2: error 920009"), std::string::npos) << nested.output;
  EXPECT_NE(nested.output.find("called from " + p("sub_mid") + " line 1, called from " + p("nested.nc") + " line 2"),
            std::string::npos)
      << nested.output;
  // the planner's error: the location only in front
  const CliResult limit = run_nck("run " + mill + " " + p("sub_limit.nc") + " --no-progress");
  EXPECT_NE(limit.output.find("sub_limit:1: error 930003: X 99999.0000 is outside the software limits"),
            std::string::npos)
      << limit.output;

  // list files: a bad number, an unknown key, text after Ende (check and run)
  const auto m = patched_example("mill", "diag_locations_lists", "tools.lis", "wz[9].radius abc");
  std::ofstream(m.dir / "zero.lis", std::ios::app) << "stray text\n";
  expect_each_location_once(run_nck("check " + m.dir.string()), "check lists", names);
  expect_each_location_once(run_nck("run " + m.dir.string() + " " + mill + "/contour.nc --no-progress"), "run lists",
                            names);
  // a PLC scenario; the command line; an output file
  const CliResult plc = run_nck("run " + mill + " " + mill + "/contour.nc --no-progress --plc " + p("bad.plc"));
  EXPECT_EQ(plc.exit_code, 2) << plc.output;
  expect_each_location_once(plc, "plc", names);
  for (const std::string& args : std::vector<std::string>{"run " + mill + " " + mill + "/contour.nc --trace-evry 2",
                                  "run " + mill + " " + mill + "/contour.nc --max-time abc", std::string("rnu"),
                                  "run " + mill + " " + p("missing.nc"),
                                  "run " + mill + " " + mill + "/contour.nc --events /nonexistent_dir/e.jsonl"}) {
    const CliResult r = run_nck(args + " --no-progress");
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
    expect_each_location_once(r, args, names);
  }
}

}  // namespace
}  // namespace nck::app::testing
