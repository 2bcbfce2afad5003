// Issue 17's command-line points that had no test of their own, each through
// the binary: '-' for stdout (point 7), diagnostics of `check` on stderr only
// (7), output-file errors with the OS reason (11), and SIGINT completing the
// report as well (8).
#include <gtest/gtest.h>

#include <csignal>
#include <fmt/format.h>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

TEST(CliPoints, DashWritesEventsTraceOrFinalToStdout) {
  const std::string run = "run " + mill() + " " + mill() + "/contour.nc --no-progress ";
  const CliResult events = run_nck_raw(run + "--events - 2>/dev/null");
  ASSERT_EQ(events.exit_code, 0);
  const auto lines = split(events.output, '\n');
  ASSERT_GT(lines.size(), 10u);
  for (const std::string& l : lines) EXPECT_TRUE(nlohmann::json::parse(l).is_object()) << l;
  EXPECT_EQ(nlohmann::json::parse(lines.back())["ev"], "end");
  const CliResult trace = run_nck_raw(run + "--trace - 2>/dev/null");
  ASSERT_EQ(trace.exit_code, 0);
  EXPECT_EQ(trace.output.rfind("t,", 0), 0u) << trace.output.substr(0, 80);
  const CliResult final_state = run_nck_raw(run + "--final - 2>/dev/null");
  ASSERT_EQ(final_state.exit_code, 0);
  EXPECT_EQ(nlohmann::json::parse(final_state.output)["end"], "program_end");
  EXPECT_EQ(nlohmann::json::parse(final_state.output)["format"], 2);  // issue 31: the layout's version
  // the summary went to stderr, not into the data
  EXPECT_EQ(final_state.output.find("simulated"), std::string::npos);
}

TEST(CliPoints, CheckPrintsDiagnosticsOnStderrOnly) {
  const auto m = patched_example("mill", "check_stderr", "tools.lis", "wz[9].radius abc");
  const CliResult out = run_nck_raw("check " + m.dir.string() + " 2>/dev/null");
  EXPECT_EQ(out.exit_code, 1);
  EXPECT_EQ(out.output, "");
  const CliResult err = run_nck_raw("check " + m.dir.string() + " 2>&1 >/dev/null");
  EXPECT_NE(err.output.find(fmt::format("tools.lis:{}: error 910003", m.line)), std::string::npos) << err.output;
}

// A warning the kernel raises (970004: #CS OFF without a CS) is printed like
// an error, with its location; list warnings count in the summary.
TEST(CliPoints, EveryWarningReachesStderrAndTheSummary) {
  const auto m = patched_example("mill", "warn_stderr", "tools.lis", "wz[9].standzeit 5");
  std::ofstream(m.dir / "p.nc") << "N10 G17 G0 X0 Y0\nN20 #CS OFF\nN30 G0 X1\nM30\n";
  const CliResult r = run_nck_raw("run " + m.dir.string() + " " + (m.dir / "p.nc").string() + " --no-progress 2>&1 >/dev/null");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(fmt::format("tools.lis:{}: warning 910002", m.line)), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("p.nc:2: warning 970004: #CS/#ACS/#ECS/#MCS OFF without an active one"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("; 4 block(s), 0 error(s), 2 warning(s)"), std::string::npos) << r.output;
}

TEST(CliPoints, OutputFileErrorsGiveTheOsReason) {
  const std::string run = "run " + mill() + " " + mill() + "/contour.nc --no-progress ";
  for (const char* opt : {"--events", "--trace", "--final", "--report"}) {
    const CliResult r = run_nck(run + opt + " /nonexistent_nck_dir/out");
    EXPECT_EQ(r.exit_code, 2) << opt << ": " << r.output;
    EXPECT_NE(r.output.find("error 940002: cannot write /nonexistent_nck_dir/out: No such file or directory"),
              std::string::npos)
        << opt << ": " << r.output;
  }
}

TEST(CliPoints, SigintCompletesTheReportToo) {
  const auto dir = temp_dir("sigint_report");
  const std::string cmd = std::string(NCK_BINARY) + " run " + mill() + " " + mill() + "/contour.nc --realtime --events " +
                          (dir / "e.jsonl").string() + " --report " + (dir / "r.html").string();
  const int status = run_and_signal(cmd, SIGINT);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_EQ(read_jsonl(dir / "e.jsonl").back()["reason"], "interrupted");
  const std::string html = read_file(dir / "r.html");
  EXPECT_NE(html.find("</html>"), std::string::npos);
  EXPECT_NE(html.find(R"("end":"interrupted")"), std::string::npos);
  EXPECT_NE(html.find(R"("exit_code":130)"), std::string::npos);
}

}  // namespace
}  // namespace nck::app::testing
