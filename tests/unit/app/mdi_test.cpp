// MDI from the PLC scenario (issue 27): blocks typed while the channel is
// idle run with the channel's modal state, offsets and tool; an error ends
// its text, never the session; MDI while a program runs is refused.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;

struct MdiRun {
  CliResult result;
  std::vector<nlohmann::json> events;
  nlohmann::json final;
};

MdiRun run_mdi(const std::string& name, const std::string& scenario, const std::string& program = "",
               const std::string& args = "") {
  const auto dir = temp_dir("mdi_" + name);
  write(dir / "s.plc", scenario);
  MdiRun r;
  r.result = run_nck("run " + mill() + " " + program + " --plc " + (dir / "s.plc").string() + " --no-progress " + args +
                     " --events " + (dir / "e.jsonl").string() + " --final " + (dir / "f.json").string());
  r.events = read_jsonl(dir / "e.jsonl");
  if (std::filesystem::exists(dir / "f.json")) r.final = nlohmann::json::parse(read_file(dir / "f.json"));
  return r;
}

double axis(const MdiRun& r, const char* name) { return r.final["channels"][0]["axes"][name]["mcs"].get<double>(); }

std::vector<std::string> states(const MdiRun& r) {
  std::vector<std::string> out;
  for (const nlohmann::json& e : r.events)
    if (e["ev"] == "state") out.push_back(e["from"].get<std::string>() + ">" + e["to"].get<std::string>());
  return out;
}

// examples/mill/mdi.plc: three blocks; the second keeps G1 F3000 from the first.
TEST(Mdi, ASessionRunsThreeBlocksWithTheModalStateCarriedOn) {
  const MdiRun r = run_mdi("three", read_file(mill() + "/mdi.plc"));
  ASSERT_EQ(r.result.exit_code, 0) << r.result.output;
  EXPECT_DOUBLE_EQ(axis(r, "X"), 10);
  EXPECT_DOUBLE_EQ(axis(r, "Y"), 20);
  EXPECT_DOUBLE_EQ(axis(r, "Z"), 5);
  std::size_t blocks = 0;
  for (const nlohmann::json& e : r.events) {
    if (e["ev"] != "block") continue;
    ++blocks;
    EXPECT_EQ(e["file"], "MDI");
  }
  EXPECT_EQ(blocks, 3u);
  // idle > running > idle for each text
  EXPECT_EQ(states(r), (std::vector<std::string>{"idle>running", "running>idle", "idle>running", "running>idle",
                                                 "idle>running", "running>idle"}));
  // Y5 -> Y20 at F3000 (50 mm/s): 15 mm take at least 0.3 s, so the G1
  // (not a rapid at 500 mm/s) ran: the second text ends after 0.3 s more.
  double starts[3] = {0, 0, 0}, ends[3] = {0, 0, 0};
  int s = 0, n = 0;
  for (const nlohmann::json& e : r.events) {
    if (e["ev"] != "state") continue;
    if (e["to"] == "running" && s < 3) starts[s++] = e["t"].get<double>();
    if (e["to"] == "idle" && n < 3) ends[n++] = e["t"].get<double>();
  }
  EXPECT_GE(ends[1] - starts[1], 15.0 / 50.0);
  EXPECT_GE(starts[2], 1.0);  // the third was typed at 1 s
}

// Lines typed together, or while the text before still moves, queue and run
// in order; the run ends when the queue is empty (issue 44, item 5: the run
// ended after the first text, and the others were dropped without a word).
TEST(Mdi, LinesTypedTogetherOrDuringAMoveAllRunInOrder) {
  const MdiRun r = run_mdi("queue", "0.0 mdi G90 G1 X10 F600\n0.0 mdi G1 Y10\n0.5 mdi G1 Z-5\n");
  ASSERT_EQ(r.result.exit_code, 0) << r.result.output;
  EXPECT_DOUBLE_EQ(axis(r, "X"), 10);
  EXPECT_DOUBLE_EQ(axis(r, "Y"), 10);
  EXPECT_DOUBLE_EQ(axis(r, "Z"), -5);
  std::vector<double> starts;
  for (const nlohmann::json& e : r.events)
    if (e["ev"] == "block") starts.push_back(e["t"].get<double>());
  ASSERT_EQ(starts.size(), 3u) << r.result.output;
  EXPECT_GE(starts[1], 1.0);  // X10 at 10 mm/s takes 1 s: Y10 waits for it
  EXPECT_GE(starts[2], 2.0);
}

// An error in MDI (a circle without centre, an unknown G code) is reported,
// the channel goes back to idle and the next text runs; the run exits 1.
TEST(Mdi, AnErrorEndsItsTextNotTheSession) {
  const MdiRun r = run_mdi("error", "0 mdi G1 X10 F3000\n0.5 mdi G2 X20 Y5\n0.6 mdi G7777\n1.0 mdi G1 Y10\n");
  EXPECT_EQ(r.result.exit_code, 1) << r.result.output;
  std::vector<long> ids;
  for (const nlohmann::json& e : r.events)
    if (e["ev"] == "error") ids.push_back(e["id"].get<long>());
  EXPECT_EQ(ids, (std::vector<long>{930005, 920005}));
  EXPECT_DOUBLE_EQ(axis(r, "X"), 10);  // the circle never ran
  EXPECT_DOUBLE_EQ(axis(r, "Y"), 10);  // the text after the errors did
  EXPECT_EQ(r.final["errors"].size(), 2u);
  const std::vector<std::string> st = states(r);
  ASSERT_FALSE(st.empty());
  EXPECT_EQ(st.back(), "running>idle");
}

// MDI while a program runs is refused (930710), nothing changes; after the
// program end it runs, and a block typed while the one before still runs
// queues up behind it; M30 typed in MDI ends like a program.
TEST(Mdi, RefusedWhileAProgramRunsAndTakenAfterItsEnd) {
  const auto dir = temp_dir("mdi_prog_program");
  write(dir / "p.nc", "N10 G0 X5\nN20 G4 X1\nN30 M30\n");
  const MdiRun r = run_mdi("prog", "0.5 mdi G0 Y3\n2.0 mdi G0 Z7\n2.02 mdi G0 X8\n2.5 mdi M30\n", (dir / "p.nc").string());
  ASSERT_EQ(r.result.exit_code, 0) << r.result.output;
  EXPECT_NE(r.result.output.find("warning 930710"), std::string::npos) << r.result.output;
  EXPECT_DOUBLE_EQ(axis(r, "X"), 8);  // typed while Z7 ran
  EXPECT_DOUBLE_EQ(axis(r, "Y"), 0);  // refused
  EXPECT_DOUBLE_EQ(axis(r, "Z"), 7);  // after the program end
  std::size_t refused = 0;
  for (const nlohmann::json& e : r.events) refused += e["ev"] == "warning" && e["id"] == 930710 && e["ch"] == 1;
  EXPECT_EQ(refused, 1u);
}

TEST(Mdi, NoProgramAndNoMdiIsBadUsage) {
  const MdiRun r = run_mdi("none", "0 feed_override 50\n");
  EXPECT_EQ(r.result.exit_code, 2) << r.result.output;
}

// A preparation thread takes MDI the same way: the same events.
TEST(Mdi, PrepThreadRunsTheSame) {
  const std::string sc = read_file(mill() + "/mdi.plc") + "1.5 mdi G2 X0 Y0\n2 mdi G1 X1\n";
  const MdiRun a = run_mdi("single", sc);
  const MdiRun b = run_mdi("threaded", sc, "", "--prep-thread");
  EXPECT_EQ(a.result.exit_code, 1) << a.result.output;
  EXPECT_EQ(a.events, b.events);
}

}  // namespace
}  // namespace nck::app
