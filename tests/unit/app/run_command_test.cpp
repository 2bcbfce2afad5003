#include <gtest/gtest.h>

#include <cmath>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

struct RunFiles {
  std::filesystem::path dir, events, trace, final_state;
  explicit RunFiles(const std::string& name)
      : dir(temp_dir(name)), events(dir / "events.jsonl"), trace(dir / "trace.csv"),
        final_state(dir / "final.json") {}
  std::string args() const {
    return "--events " + events.string() + " --trace " + trace.string() + " --final " +
           final_state.string();
  }
};

TEST(RunCommand, MillExampleRunsToM30WithAllOutputs) {
  RunFiles f("mill");
  CliResult r = run_nck("run " + root() + "/examples/mill " + root() + "/examples/mill/contour.nc " + f.args());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto events = read_jsonl(f.events);
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.back()["ev"], "end");
  EXPECT_EQ(events.back()["reason"], "M30");
  // time order, and every block event names its line and file
  double t = 0;
  for (const json& e : events) {
    EXPECT_GE(e["t"].get<double>(), t);
    t = e["t"].get<double>();
    EXPECT_EQ(e["ch"], 1);
    if (e["ev"] == "block") {
      EXPECT_TRUE(e.contains("line") && e.contains("n") && e.contains("file"));
    }
  }
  // trace: header, consistent rows, final row at X0 Y0 Z? after the last move
  const auto lines = split(read_file(f.trace), '\n');
  ASSERT_GT(lines.size(), 100u);
  const auto header = split(lines[0], ',');
  EXPECT_EQ(header[0], "t");
  EXPECT_EQ(header[1], "X");
  EXPECT_EQ(header[2], "Y");
  EXPECT_EQ(header[3], "Z");
  EXPECT_NE(std::find(header.begin(), header.end(), "S1.rpm"), header.end());
  EXPECT_NE(std::find(header.begin(), header.end(), "S2.act_rpm"), header.end());
  // the mill configures 3D distance control (FCT_3D_DIST_CTRL): its offset is traced
  EXPECT_NE(std::find(header.begin(), header.end(), "dist.offset"), header.end());
  for (std::size_t i = 1; i < lines.size(); ++i) EXPECT_EQ(split(lines[i], ',').size(), header.size());
  // final state: X0 Y0 and Z at 10 + 20 (G91 retract) ... whatever the program says
  const json fin = json::parse(read_file(f.final_state));
  EXPECT_NEAR(fin["channels"][0]["axes"]["X"]["mcs"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(fin["channels"][0]["axes"]["Y"]["mcs"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(fin["channels"][0]["axes"]["Z"]["mcs"].get<double>(), 22.0, 1e-9);
  EXPECT_EQ(fin["channels"][0]["main_spindle"], "S1");
  EXPECT_TRUE(fin["errors"].empty());
  EXPECT_GT(fin["time"].get<double>(), 1.0);
}

TEST(RunCommand, TraceEveryThinsTheRows) {
  RunFiles a("every1"), b("every10");
  const std::string prog = root() + "/examples/lathe " + root() + "/examples/lathe/turn.nc";
  ASSERT_EQ(run_nck("run " + prog + " --trace " + a.trace.string()).exit_code, 0);
  ASSERT_EQ(run_nck("run " + prog + " --trace " + b.trace.string() + " --trace-every 10").exit_code, 0);
  const auto rows1 = split(read_file(a.trace), '\n').size() - 1;
  const auto rows10 = split(read_file(b.trace), '\n').size() - 1;
  EXPECT_NEAR(static_cast<double>(rows10), static_cast<double>(rows1) / 10.0, 1.0);
}

TEST(RunCommand, TwoChannelsEachRunTheirProgram) {
  RunFiles f("two");
  const std::string ex = root() + "/examples/two-channel";
  CliResult r = run_nck("run " + ex + " " + ex + "/channel1.nc " + ex + "/channel2.nc " + f.args());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  int ends = 0;
  for (const json& e : read_jsonl(f.events))
    if (e["ev"] == "end") {
      ++ends;
      EXPECT_EQ(e["reason"], "M30");
    }
  EXPECT_EQ(ends, 2);
  const auto header = split(split(read_file(f.trace), '\n')[0], ',');
  EXPECT_NE(std::find(header.begin(), header.end(), "2.X"), header.end());
}

TEST(RunCommand, NcErrorAbortsWithExit1AndCompleteFiles) {
  RunFiles f("ncerror");
  const auto prog = f.dir / "bad.nc";
  std::ofstream(prog) << "%bad\nN10 G0 X10\nN20 G1 X20 F0\nN30 M30\n";
  CliResult r = run_nck("run " + root() + "/examples/mill " + prog.string() + " " + f.args());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("bad.nc:3: error 930002"), std::string::npos) << r.output;
  const auto events = read_jsonl(f.events);
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events[events.size() - 2]["ev"], "error");
  EXPECT_EQ(events[events.size() - 2]["id"], 930002);
  EXPECT_EQ(events[events.size() - 2]["line"], 3);
  EXPECT_EQ(events.back()["reason"], "error");
  const json fin = json::parse(read_file(f.final_state));
  ASSERT_EQ(fin["errors"].size(), 1u);
  EXPECT_NEAR(fin["channels"][0]["axes"]["X"]["mcs"].get<double>(), 10.0, 1e-9);
}

TEST(RunCommand, DecoderErrorStopsTheRunAtItsLine) {
  RunFiles f("decerr");
  const auto prog = f.dir / "bad.nc";
  std::ofstream(prog) << "%bad\nN10 G0 X10\nN20 G1 X[1/0] F100\nN30 M30\n";
  CliResult r = run_nck("run " + root() + "/examples/mill " + prog.string() + " " + f.args());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const auto events = read_jsonl(f.events);
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events[events.size() - 2]["ev"], "error");
  EXPECT_EQ(events[events.size() - 2]["line"], 3);
}

TEST(RunCommand, MaxTimeEndsTheRun) {
  RunFiles f("maxtime");
  CliResult r = run_nck("run " + root() + "/examples/mill " + root() + "/examples/mill/contour.nc --max-time 0.5 " + f.args());
  EXPECT_EQ(r.exit_code, 1);
  const auto events = read_jsonl(f.events);
  EXPECT_EQ(events.back()["reason"], "max_time");
  EXPECT_NEAR(json::parse(read_file(f.final_state))["time"].get<double>(), 0.5, 0.002);
}

TEST(RunCommand, BadUsageAndBadMachineExit2) {
  EXPECT_EQ(run_nck("run").exit_code, 2);
  EXPECT_EQ(run_nck("frobnicate").exit_code, 2);
  EXPECT_EQ(run_nck("run /nonexistent/machine x.nc").exit_code, 2);
  EXPECT_EQ(run_nck("run " + root() + "/examples/mill a.nc b.nc c.nc").exit_code, 2);
  EXPECT_EQ(run_nck("run " + root() + "/examples/mill " + root() + "/examples/mill/contour.nc --trace-every 0").exit_code, 2);
}

TEST(RunCommand, UnwritableOutputIsExit2) {
  CliResult r = run_nck("run " + root() + "/examples/mill " + root() +
                        "/examples/mill/contour.nc --events /nonexistent/dir/e.jsonl");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("940002"), std::string::npos);
}


std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

TEST(RunCommand, ReportIsASelfContainedPageWithPlots) {
  const auto dir = temp_dir("report");
  const std::string ex = root() + "/examples/mill";
  CliResult r = run_nck("run " + ex + " " + ex + "/spindle.nc --report " + (dir / "r.html").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string html = read_file(dir / "r.html");
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("</html>"), std::string::npos);
  EXPECT_EQ(count(html, "<svg"), 3u);  // the channel's axes, the spindles, distance control (the mill has it)
  EXPECT_NE(html.find("sensor, offset, distance error (mm)"), std::string::npos);
  EXPECT_EQ(count(html, "<svg"), count(html, "</svg>"));
  EXPECT_NE(html.find(">S1.rpm<"), std::string::npos);
  EXPECT_NE(html.find(">X<"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);  // nothing to load or run
  EXPECT_EQ(html.find("http://"), html.find("http://www.w3.org/2000/svg"));
}

TEST(RunCommand, ReportOfAnAbortedRunListsTheError) {
  const auto dir = temp_dir("report_err");
  std::ofstream(dir / "bad.nc") << "%bad\nN10 G1 X20 F0\nN20 M30\n";
  CliResult r = run_nck("run " + root() + "/examples/mill " + (dir / "bad.nc").string() + " --report " +
                        (dir / "r.html").string());
  EXPECT_EQ(r.exit_code, 1);
  const std::string html = read_file(dir / "r.html");
  EXPECT_NE(html.find("Errors</h2>"), std::string::npos);
  EXPECT_NE(html.find("930002"), std::string::npos);
  EXPECT_NE(html.find("</html>"), std::string::npos);
}

}  // namespace
}  // namespace nck::app
