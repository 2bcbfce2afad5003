// Robustness review reproducers (issue 10), each through the nck binary:
// no crash, no hang, no lost or destroyed output on any input.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

// Finding 1: bytes that are not UTF-8 (a Latin-1 'ä' in a comment, N\xff).
TEST(Robustness, Latin1BytesReachJsonAsUtf8NotAnAbort) {
  const auto dir = temp_dir("latin1");
  const auto p = write(dir / "p.nc", "N10 G0 X0 (Kommentar \xe4)\nN\xff\nM30\n");
  CliResult r = run_nck("run " + mill() + " " + p.string() + " --events " + (dir / "e.jsonl").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;  // the bad block is an NC error, not a signal
  const auto events = read_jsonl(dir / "e.jsonl");  // every line parses as JSON
  ASSERT_FALSE(events.empty());
  bool found = false;
  for (const auto& e : events)
    if (e["ev"] == "error") found = e["msg"].get<std::string>().find("\xc3\xbf") != std::string::npos;  // 'ÿ'
  EXPECT_TRUE(found);
  // A Latin-1 comment alone is read, not rejected.
  const auto ok = write(dir / "ok.nc", "N10 G0 X0 (Kommentar \xe4)\nM30\n");
  EXPECT_EQ(run_nck("run " + mill() + " " + ok.string()).exit_code, 0);
}

// Finding 2: structures that never close end parse, check and run with an error.
TEST(Robustness, UnclosedStructuresEndWithAnErrorInEveryMode) {
  const auto dir = temp_dir("unclosed");
  const std::pair<const char*, const char*> cases[] = {
      {"if.nc", "$IF 1\nG0 X1\n"},
      {"var.nc", "#VAR\nV.P.A = 1\n"},
      {"if_m30.nc", "$IF 1\nG0 X1\nM30\n"},  // an M30 after it does not hide the missing $ENDIF
  };
  for (const auto& [name, text] : cases) {
    const auto p = write(dir / name, text);
    CliResult parse = run_nck("parse " + p.string());
    EXPECT_EQ(parse.exit_code, 1) << name << parse.output;
    CliResult run = run_nck("run " + mill() + " " + p.string());
    EXPECT_EQ(run.exit_code, 1) << name << run.output;
    EXPECT_TRUE(parse.output.find("920041") != std::string::npos || parse.output.find("920025") != std::string::npos)
        << name << parse.output;
  }
  // $IF .. M30 .. $ENDIF is fine: the structure closes after the program end.
  const auto fine = write(dir / "fine.nc", "$IF 1\nG0 X1\nM30\n$ENDIF\n");
  EXPECT_EQ(run_nck("parse " + fine.string()).exit_code, 0);
}

// Finding 2: lint reports an error inside a loop body once, and terminates.
TEST(Robustness, LintReportsAnErrorInALoopOnce) {
  const auto dir = temp_dir("lint_loop");
  const auto p = write(dir / "p.nc", "$FOR P1=1,1000\nX[FOO]\n$ENDFOR\nM30\n");
  CliResult r = run_nck("parse " + p.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(count(r.output, "p.nc:2:"), 1u) << r.output;
  // An unterminated $IF in a subroutine called in a loop: one error, an end.
  write(dir / "sub.nc", "$IF 1\nG0 X1\nM17\n");
  const auto q = write(dir / "q.nc", "$FOR P1=1,100000\nL sub.nc\n$ENDFOR\nM30\n");
  CliResult s = run_nck("parse " + q.string());
  EXPECT_EQ(s.exit_code, 1) << s.output;
  EXPECT_EQ(count(s.output, "920041"), 1u) << s.output;
}

// Finding 3: one loop budget per run; nested loops do not multiply it.
TEST(Robustness, NestedLoopsShareOneBudget) {
  const auto dir = temp_dir("budget");
  const auto p = write(dir / "p.nc", "$WHILE 1\n$FOR P1=1,1000\n$ENDFOR\n$ENDWHILE\nM30\n");
  const auto t0 = std::chrono::steady_clock::now();
  CliResult r = run_nck("run " + mill() + " " + p.string() + " --events " + (dir / "e.jsonl").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("920042"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("line 2"), std::string::npos) << r.output;  // names the loop
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(120));
}

// Finding 4: program variables have a total memory cap.
TEST(Robustness, VariableArraysHaveAMemoryCap) {
  const auto dir = temp_dir("var_cap");
  std::string text = "#VAR\n";
  for (int i = 0; i < 200; ++i) text += "V.P.A" + std::to_string(i) + "[100000]\n";
  text += "#ENDVAR\nM30\n";
  CliResult r = run_nck("parse " + write(dir / "p.nc", text).string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("920085"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("p.nc:12:"), std::string::npos) << r.output;  // the 11th array passes the cap
}

// Finding 5: a failed write is an error and a non-zero exit.
TEST(Robustness, WritesToAFullDeviceFail) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  CliResult run = run_nck("run " + mill() + " " + mill() + "/contour.nc --events /dev/full");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("940002"), std::string::npos);
  for (const char* cmd : {"params", "errors"}) {
    CliResult r = run_nck_raw(std::string(cmd) + " 2>&1 >/dev/full");  // stderr to the pipe
    EXPECT_EQ(r.exit_code, 2) << cmd << r.output;
    EXPECT_NE(r.output.find("940002"), std::string::npos) << cmd;
  }
}

// Finding 7: outputs never destroy inputs, nor each other.
TEST(Robustness, AnOutputPathThatIsAnInputIsRefused) {
  const auto dir = temp_dir("clobber");
  const std::string program = "N10 G0 X1\nM30\n";
  const auto p = write(dir / "p.nc", program);
  CliResult r = run_nck("run " + mill() + " " + p.string() + " --events " + p.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("940004"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(p), program);
  CliResult twice = run_nck("run " + mill() + " " + p.string() + " --events " + (dir / "a").string() +
                            " --trace " + (dir / "." / "a").string());
  EXPECT_EQ(twice.exit_code, 2) << twice.output;
  CliResult list = run_nck("run " + mill() + " " + p.string() + " --final " + mill() + "/x.lis");
  EXPECT_EQ(list.exit_code, 2) << list.output;
}

// Finding 7: one output that cannot be written does not cost the others,
// and no temporary file is left behind.
TEST(Robustness, AFailedOutputKeepsTheOthersAndLeavesNoTemporary) {
  const auto dir = temp_dir("keep_old");
  const auto p = write(dir / "p.nc", "N10 G0 X1\nM30\n");
  write(dir / "e.jsonl", "previous\n");
  // The events are fine, but --final names a folder that does not exist: exit 2.
  CliResult r = run_nck("run " + mill() + " " + p.string() + " --events " + (dir / "e.jsonl").string() +
                        " --final " + (dir / "missing" / "f.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  // Events were complete, so they replaced the old file; no temporary is left.
  EXPECT_NE(read_file(dir / "e.jsonl"), "previous\n");
  for (const auto& f : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(f.path().string().find(".tmp"), std::string::npos) << f.path();
}

// Finding 6: SIGINT / SIGTERM stop the run with every file complete.
TEST(Robustness, SignalsEndTheRunWithCompleteFiles) {
  const auto dir = temp_dir("signals");
  for (int sig : {SIGINT, SIGTERM}) {
    const std::string cmd = std::string(NCK_BINARY) + " run " + mill() + " " + mill() +
                            "/contour.nc --realtime --events " + (dir / "e.jsonl").string() + " --trace " +
                            (dir / "t.csv").string() + " --final " + (dir / "f.json").string();
    const int status = run_and_signal(cmd, sig);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), sig == SIGINT ? 130 : 143);
    const auto events = read_jsonl(dir / "e.jsonl");  // every line complete JSON
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(events.back()["reason"], "interrupted");
    const auto final_state = nlohmann::json::parse(read_file(dir / "f.json"));
    EXPECT_EQ(final_state["end"], "interrupted");
    EXPECT_GT(final_state["time"].get<double>(), 0.1);
    const std::string trace = read_file(dir / "t.csv");
    EXPECT_EQ(trace.back(), '\n');
  }
}

// Finding 8: an error inside a subroutine names the subroutine's file and line,
// and the call chain.
TEST(Robustness, SubroutineErrorsNameTheirFileAndCaller) {
  const auto dir = temp_dir("sub_error");
  write(dir / "sub.nc", "G0 X1\nG0 X2\nX[FOO]\nM17\n");
  const auto p = write(dir / "p.nc", "N10 G0 X0\nL sub.nc\nM30\n");
  CliResult r = run_nck("run " + mill() + " " + p.string() + " --events " + (dir / "e.jsonl").string());
  EXPECT_EQ(r.exit_code, 1);
  bool found = false;
  for (const auto& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "error") {
      EXPECT_NE(e["file"].get<std::string>().find("sub.nc"), std::string::npos) << e;
      EXPECT_EQ(e["line"], 3);
      EXPECT_NE(e["msg"].get<std::string>().find("called from"), std::string::npos) << e;
      found = true;
    }
  EXPECT_TRUE(found);
}

// Finding 9: the smaller ones.
TEST(Robustness, PlcDirectoryEmptyListAndDeepBrackets) {
  const auto dir = temp_dir("smaller");
  CliResult plc = run_nck("run " + mill() + " " + mill() + "/contour.nc --plc " + dir.string());
  EXPECT_EQ(plc.exit_code, 2);
  EXPECT_NE(plc.output.find("940003"), std::string::npos) << plc.output;

  const auto m = patched_example("mill", "empty_list", "zero.lis", "");
  std::ofstream(m.dir / "zero.lis") << "";
  CliResult check = run_nck("check " + m.dir.string());
  EXPECT_NE(check.output.find("910028"), std::string::npos) << check.output;

  const std::string open(70, '['), close(70, ']');
  const auto p = write(dir / "deep.nc", "N10 X" + open + "1" + close + "\nM30\n");
  CliResult deep = run_nck("parse " + p.string());
  EXPECT_EQ(deep.exit_code, 1);
  EXPECT_NE(deep.output.find("920084"), std::string::npos) << deep.output;
}

}  // namespace
}  // namespace nck::app::testing
