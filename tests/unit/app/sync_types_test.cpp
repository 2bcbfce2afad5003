// Every synchronisation type of FCT-S1 2.5 through `nck run`: the mill's S1
// gets the type as m3_sync, and the events show when M3 is executed and
// where the path waits for speed reached.
#include <gtest/gtest.h>

#include <map>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

// N20 moves only 0.5 mm, so the spindle (6000 rpm, about 1.8 s run-up) is
// still accelerating at every later block.
constexpr const char* kProgram =
    "%sync\nN10 G0 X0\nN20 G1 X0.5 F3000 S6000 M3\nN30 G0 X20\nN40 G1 X30\nN50 #EXPL SYN\nN60 M30\n";

struct Timeline {
  std::map<long, double> block_t;       // N -> start time
  std::vector<std::pair<long, double>> waits;  // line -> time of each wait event
  double spindle_start = -1;            // first S1 rotate event
  bool plc_out = false;
};

Timeline run_with(const std::string& sync, const std::string& name) {
  const auto machine = patched_example("mill", name, "channel1.lis", "spindel[0].m3_synch " + sync).dir;
  const auto dir = machine.parent_path();
  std::ofstream(dir / "p.nc") << kProgram;
  CliResult r = run_nck("run " + machine.string() + " " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string());
  EXPECT_EQ(r.exit_code, 0) << sync << "\n" << r.output;
  Timeline tl;
  for (const json& e : read_jsonl(dir / "e.jsonl")) {
    if (e["ev"] == "block" && !e["n"].is_null()) tl.block_t[e["n"].get<long>()] = e["t"];
    if (e["ev"] == "wait") tl.waits.emplace_back(e["line"].get<long>(), e["t"].get<double>());
    if (e["ev"] == "spindle" && e["mode"] == "rotate" && tl.spindle_start < 0) tl.spindle_start = e["t"];
    if (e["ev"] == "plc_out" && e["fn"] == "M3") tl.plc_out = true;
  }
  return tl;
}

TEST(SyncTypes, NoSynchDoesNotExecuteTheFunction) {
  Timeline t = run_with("NO_SYNCH", "nosynch");
  EXPECT_LT(t.spindle_start, 0);
  EXPECT_TRUE(t.waits.empty());
}

TEST(SyncTypes, MosStartsWithoutWaitingAndWithoutOutput) {
  Timeline t = run_with("MOS", "mos");
  EXPECT_DOUBLE_EQ(t.spindle_start, t.block_t[20]);
  EXPECT_TRUE(t.waits.empty());
  EXPECT_FALSE(t.plc_out);  // NC spindle: only PLC_INFO outputs to the PLC
}

TEST(SyncTypes, MvsSvsWaitsBeforeTheMotion) {
  Timeline t = run_with("MVS_SVS", "svs");
  ASSERT_EQ(t.waits.size(), 1u);
  EXPECT_EQ(t.waits[0].first, 3);  // line of N20
  EXPECT_DOUBLE_EQ(t.waits[0].second, t.block_t[20]);
  EXPECT_GT(t.block_t[30] - t.block_t[20], 1.5);  // run-up, then 0.5 mm
}

TEST(SyncTypes, MvsSnsOutputsBeforeAndWaitsAfterTheMotion) {
  Timeline t = run_with("MVS_SNS", "sns");
  EXPECT_DOUBLE_EQ(t.spindle_start, t.block_t[20]);
  ASSERT_EQ(t.waits.size(), 1u);
  EXPECT_GT(t.waits[0].second, t.block_t[20]);  // at the end of N20's motion
  EXPECT_LT(t.waits[0].second, t.block_t[20] + 0.1);
  EXPECT_GT(t.block_t[30] - t.block_t[20], 1.5);
}

TEST(SyncTypes, MnsSnsOutputsAfterTheMotion) {
  Timeline t = run_with("MNS_SNS", "mns");
  EXPECT_GT(t.spindle_start, t.block_t[20]);
  ASSERT_EQ(t.waits.size(), 1u);
  EXPECT_NEAR(t.waits[0].second, t.spindle_start, 0.0015);  // the wait is checked in the next cycle
  EXPECT_GT(t.block_t[30] - t.block_t[20], 1.5);
}

TEST(SyncTypes, MvsSlmWaitsAtTheNextFeedMove) {
  Timeline t = run_with("MVS_SLM", "slm");
  EXPECT_DOUBLE_EQ(t.spindle_start, t.block_t[20]);
  ASSERT_EQ(t.waits.size(), 1u);
  EXPECT_EQ(t.waits[0].first, 5);  // N40 G1 (N30 is G0: no synchronisation there)
  EXPECT_LT(t.block_t[30] - t.block_t[20], 0.1);
}

TEST(SyncTypes, MvsSlpWaitsAtExplSyn) {
  Timeline t = run_with("MVS_SLP", "slp");
  EXPECT_DOUBLE_EQ(t.spindle_start, t.block_t[20]);
  ASSERT_EQ(t.waits.size(), 1u);
  EXPECT_EQ(t.waits[0].first, 6);  // N50 #EXPL SYN
}

TEST(SyncTypes, PlcInfoAddsTheAcknowledgement) {
  Timeline t = run_with("PLC_INFO | MVS_SVS", "plcinfo");
  EXPECT_TRUE(t.plc_out);
  ASSERT_EQ(t.waits.size(), 2u);  // first for the PLC, then for speed reached
  EXPECT_EQ(t.waits[0].first, 3);
}

// NO_SYNCH means "no output of S/M function to PLC" (FCT-S1 2.5): the speed
// itself is still commanded (only M3/M4/M5/M19 are not executed), nothing is
// output or waited for, and `nck check` says so with 910029 on the list line.
TEST(SyncTypes, NoSynchSpeedIsCommandedWithoutOutputAndCheckExplains) {
  const auto patched = patched_example("mill", "snosynch", "channel1.lis", "spindel[0].s_synch NO_SYNCH");
  const auto dir = patched.dir.parent_path();
  std::ofstream(dir / "p.nc") << "M3 S1000\nG4 X1\nS2000\nG4 X1\nM30\n";
  CliResult r = run_nck("run " + patched.dir.string() + " " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<double> rpm;
  bool s_out = false, s_wait = false;
  for (const json& e : read_jsonl(dir / "e.jsonl")) {
    if (e["ev"] == "spindle" && e["mode"] == "rotate") rpm.push_back(e["rpm"]);
    if (e["ev"] == "plc_out" && e["fn"] == "S") s_out = true;
    if (e["ev"] == "wait" && e["fn"] == "S") s_wait = true;
  }
  EXPECT_EQ(rpm, (std::vector<double>{1000, 2000}));
  EXPECT_FALSE(s_out);
  EXPECT_FALSE(s_wait);
  CliResult c = run_nck("check " + patched.dir.string());
  EXPECT_EQ(c.exit_code, 0) << c.output;
  EXPECT_NE(c.output.find("channel1.lis:" + std::to_string(patched.line) + ": warning 910029"),
            std::string::npos)
      << c.output;
}

// With gear change off, M40..M45 are free M functions (FCT-S1 2.8.2 and
// §3.2.1, P-CHAN-00052): m_synch[41] MVS_SVS with a 1 s acknowledgement holds the path.
TEST(SyncTypes, FreeGearMFunctionFollowsItsMSynch) {
  const auto patched = patched_example("mill", "m41synch", "channel1.lis", "m_synch[41] MVS_SVS");
  const auto dir = patched.dir.parent_path();
  std::string sim = read_file(patched.dir / "sim.lis");
  sim.insert(sim.rfind("Ende"), "m_ack_delay_ms[41] 1000\n");
  std::ofstream(patched.dir / "sim.lis") << sim;
  std::ofstream(dir / "p.nc") << "N10 M41 G1 X10 F6000\nN20 M30\n";
  CliResult r = run_nck("run " + patched.dir.string() + " " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string() + " --trace " + (dir / "t.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  double out_t = -1, ack_t = -1;
  for (const json& e : read_jsonl(dir / "e.jsonl")) {
    if (e["ev"] == "plc_out" && e["fn"] == "M41") out_t = e["t"];
    if (e["ev"] == "plc_ack" && e["fn"] == "M41") ack_t = e["t"];
  }
  EXPECT_DOUBLE_EQ(out_t, 0.0);
  EXPECT_NEAR(ack_t, 1.0, 1e-9);
  // X still at 0 until the acknowledgement.
  for (const std::string& line : split(read_file(dir / "t.csv"), '\n')) {
    const auto c = split(line, ',');
    if (c.size() < 2 || c[0] == "t" || std::stod(c[0]) >= 1.0) continue;
    EXPECT_EQ(std::stod(c[1]), 0.0) << line;
  }
}

// Channel M functions synchronise by m_synch[n] (mill: M6 MVS_SVS with a
// 1.5 s acknowledgement in sim.lis, M8 MOS, M10 PLC_INFO MVS_SNS).
TEST(SyncTypes, ChannelMFunctionsFollowTheirMSynch) {
  const auto dir = temp_dir("msynch");
  std::ofstream(dir / "p.nc") << "%m\nN10 M6 G1 X1 F600\nN20 M8 X2\nN30 M10 X3\nN40 M30\n";
  CliResult r = run_nck("run " + root() + "/examples/mill " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::map<std::string, double> out_t, ack_t, wait_t;
  std::map<long, double> block_t;
  for (const json& e : read_jsonl(dir / "e.jsonl")) {
    const std::string ev = e["ev"];
    if (ev == "plc_out") out_t[e["fn"]] = e["t"];
    if (ev == "plc_ack") ack_t[e["fn"]] = e["t"];
    if (ev == "wait") wait_t[e["fn"]] = e["t"];
    if (ev == "block") block_t[e["n"].get<long>()] = e["t"];
  }
  EXPECT_NEAR(ack_t["M6"] - out_t["M6"], 1.5, 1e-9);       // m_ack_delay_ms[6]
  EXPECT_DOUBLE_EQ(wait_t["M6"], block_t[10]);             // before the motion
  EXPECT_GE(block_t[20] - block_t[10], 1.5);
  EXPECT_EQ(wait_t.count("M8"), 0u);                       // MOS: no wait
  EXPECT_DOUBLE_EQ(out_t["M10"], block_t[30]);             // output before the motion ...
  EXPECT_GT(ack_t["M10"], out_t["M10"]);
  EXPECT_GE(block_t[40], ack_t["M10"]);                    // ... synchronised after it
}

// The mill with M20 as an MVS_SLM function (waited for at the next feed
// motion), and a program with `late` M20 blocks before its first G1.
PatchedMachine late_waits(const std::string& name, int late) {
  const auto m = patched_example("mill", name, "channel1.lis", "m_synch[20]  MVS_SLM");
  std::string program = "N1 G0 X0\n";
  for (int i = 0; i < late; ++i) program += "M20\n";
  program += "G1 X10 F1000\nM30\n";
  std::ofstream(m.dir / "p.nc") << program;
  return m;
}

// A channel holds 16 late waits; the 17th is error 930014 instead of a
// silently lost wait.
TEST(SyncTypes, TooManyLateWaitsIsAnErrorNotALostWait) {
  const auto m = late_waits("late_waits", 17);
  CliResult r = run_nck("run " + m.dir.string() + " " + (m.dir / "p.nc").string() + " --events " +
                        (m.dir / "e.jsonl").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  std::vector<nlohmann::json> errors;
  for (const auto& e : read_jsonl(m.dir / "e.jsonl"))
    if (e["ev"] == "error") errors.push_back(e);
  ASSERT_EQ(errors.size(), 1u) << r.output;
  EXPECT_EQ(errors[0]["id"], 930014);
  EXPECT_EQ(errors[0]["line"], 18);  // the 17th M20
}

// 16 late waits fit and are all taken at the G1 (the bound is exact).
TEST(SyncTypes, SixteenLateWaitsFit) {
  const auto m = late_waits("late_waits_fit", 16);
  CliResult r = run_nck("run " + m.dir.string() + " " + (m.dir / "p.nc").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

}  // namespace

// FCT-S1 2.5.2, second example, as written (s_sync 0x2, m3_sync 0x1, no S
// before N10): M3 selects the direction at 0 rpm (TF5200 M03) and is no error;
// N20's S500 turns the spindle in the M3 direction and the path waits for
// the speed before N20's motion, N30 waits for 100 rpm before its motion.
TEST(SyncTypes, SeedSecondExampleSpindleSynchronousWithThePath) {
  const auto patched = patched_example("mill", "seedsync2", "channel1.lis",
                                       "spindel[0].s_synch 0x00000002\nspindel[0].m3_synch 0x00000001");
  const auto dir = patched.dir.parent_path();
  std::ofstream(dir / "p.nc") << "N10 M3 X0 Y0 G0\nN20 X40 Y40 G1 F1500 S500\nN30 S100 X0 Y0\nN40 M30\n";
  CliResult r = run_nck("run " + patched.dir.string() + " " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string() + " --trace " + (dir / "t.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<double> rotate_rpm;
  std::map<long, double> wait_end_t;  // line -> end of its speed_reached wait
  for (const json& e : read_jsonl(dir / "e.jsonl")) {
    if (e["ev"] == "spindle" && e["mode"] == "rotate") rotate_rpm.push_back(e["rpm"].get<double>());
    if (e["ev"] == "wait_end" && e["reason"] == "speed_reached") wait_end_t[e["line"].get<long>()] = e["t"];
    EXPECT_NE(e["ev"], "error") << e.dump();
  }
  EXPECT_EQ(rotate_rpm, (std::vector<double>{500.0, 100.0}));  // positive: the M3 direction
  ASSERT_EQ(wait_end_t.size(), 2u);
  ASSERT_TRUE(wait_end_t.contains(2) && wait_end_t.contains(3));
  // X and Y stay at 0 until the spindle reached 500 rpm.
  for (const std::string& line : split(read_file(dir / "t.csv"), '\n')) {
    const auto c = split(line, ',');
    if (c.size() < 3 || c[0] == "t" || std::stod(c[0]) >= wait_end_t[2] - 1e-9) continue;
    EXPECT_EQ(std::stod(c[1]), 0.0) << line;
  }
  EXPECT_GT(wait_end_t[2], 0.1);
}

}  // namespace nck::app
