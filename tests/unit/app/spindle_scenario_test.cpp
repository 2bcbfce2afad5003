// Spindle functions end to end through `nck run`: the seed's examples as
// events (FCT-S1 2.4.1 override, 2.5.2 synchronisation, 2.8.2 gear change),
// drive scaling in the trace, and the errors of bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

std::filesystem::path patched(const std::string& example, const std::string& name,
                              const std::string& file, const std::string& lines) {
  return patched_example(example, name, file, lines).dir;
}

struct RunResult {
  int exit_code;
  std::string output;
  std::vector<json> events;
  std::filesystem::path dir;
};

RunResult run(const std::filesystem::path& machine, const std::string& program_text, const std::string& args = "") {
  RunResult r;
  r.dir = temp_dir("prog");
  std::ofstream(r.dir / "p.nc") << program_text;
  CliResult c = run_nck("run " + machine.string() + " " + (r.dir / "p.nc").string() + " --events " +
                        (r.dir / "e.jsonl").string() + " " + args);
  r.exit_code = c.exit_code;
  r.output = c.output;
  r.events = read_jsonl(r.dir / "e.jsonl");
  return r;
}

std::vector<json> of_kind(const std::vector<json>& events, const std::string& ev) {
  std::vector<json> out;
  std::copy_if(events.begin(), events.end(), std::back_inserter(out),
               [&](const json& e) { return e["ev"] == ev; });
  return out;
}

double block_time(const std::vector<json>& events, long n) {
  for (const json& e : events)
    if (e["ev"] == "block" && e["n"] == n) return e["t"].get<double>();
  return -1;
}

TEST(SpindleScenario, OverrideAndG167FollowTheSeedExample) {
  const std::string ex = root() + "/examples/mill";
  const auto dir = temp_dir("ovr");
  CliResult c = run_nck("run " + ex + " " + ex + "/spindle.nc --plc " + ex + "/spindle.plc --events " +
                        (dir / "e.jsonl").string());
  ASSERT_EQ(c.exit_code, 0) << c.output;
  std::vector<double> s1;
  for (const json& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "spindle" && e["spindle"] == "S1" && e["mode"] == "rotate") s1.push_back(e["rpm"]);
  // 50 % override: 1000 -> 500; G167: 1000; the next speed 3000 -> 1500.
  ASSERT_GE(s1.size(), 3u);
  EXPECT_DOUBLE_EQ(s1[0], 500.0);
  EXPECT_DOUBLE_EQ(s1[1], 1000.0);
  EXPECT_DOUBLE_EQ(s1[2], 1500.0);
}

// FCT-S1 2.5.2: s_sync MVS_SVS, m3_sync MOS.
std::filesystem::path sync_example_machine(const std::string& name) {
  return patched("mill", name, "channel1.lis",
                 "spindel[0].s_synch MVS_SVS\nspindel[0].m3_synch MOS\n");
}

TEST(SpindleScenario, SeedSyncExample1PathDoesNotWaitBecauseOfM3) {
  RunResult r = run(sync_example_machine("sync1"),
              "%s\nN10 X0 Y0 G0\nN20 X40 Y40 G1 F1500 M3 S500\nN30 M3 S100 X0 Y0\nN40 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(of_kind(r.events, "wait").empty());  // M3 (MOS) decides over S: no wait
  // N30 starts when N20's motion ends, not when the spindle reaches 500 rpm.
  const double n20 = block_time(r.events, 20), n30 = block_time(r.events, 30);
  const double travel_s = std::hypot(40.0, 40.0) / (1500.0 / 60.0);
  EXPECT_NEAR(n30 - n20, travel_s, 0.05);
}

TEST(SpindleScenario, SeedSyncExample2PathWaitsForSpeedReached) {
  RunResult r = run(sync_example_machine("sync2"),
              "%s\nN5 S200\nN10 M3 X0 Y0 G0\nN20 X40 Y40 G1 F1500 S500\nN30 S100 X0 Y0\nN40 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<long> waited;
  for (const json& e : of_kind(r.events, "wait")) {
    EXPECT_EQ(e["reason"], "speed_reached");
    EXPECT_EQ(e["spindle"], "S1");
    waited.push_back(e["line"].get<long>());
  }
  EXPECT_EQ(waited, (std::vector<long>{4, 5}));  // N20 and N30, before their motion
  // The motion of N20 starts only after speed reached.
  double reached = -1;
  for (const json& e : of_kind(r.events, "wait_end"))
    if (e["line"] == 4) reached = e["t"].get<double>();
  ASSERT_GT(reached, 0);
  EXPECT_GT(block_time(r.events, 30) - reached, std::hypot(40.0, 40.0) / 25.0 - 0.05);
}

TEST(SpindleScenario, AutomaticGearChangeOnTheLathe) {
  const std::string ex = root() + "/examples/lathe";
  const auto dir = temp_dir("gears");
  CliResult c = run_nck("run " + ex + " " + ex + "/gears.nc --events " + (dir / "e.jsonl").string());
  ASSERT_EQ(c.exit_code, 0) << c.output;
  const auto events = read_jsonl(dir / "e.jsonl");
  std::vector<std::string> changes;
  for (const json& e : of_kind(events, "gear")) changes.push_back(e["fn"]);
  EXPECT_EQ(changes, (std::vector<std::string>{"M41", "M42"}));  // S700 keeps stage 1
  // The change waits for the PLC (gear_change_time_ms 800 in sim.lis).
  double out = -1, ack = -1;
  for (const json& e : events) {
    if (e["ev"] == "plc_out" && e["fn"] == "M41") out = e["t"];
    if (e["ev"] == "plc_ack" && e["fn"] == "M41") ack = e["t"];
  }
  EXPECT_NEAR(ack - out, 0.8, 1e-6);
}

TEST(SpindleScenario, SensorlessSpindleDriveValueFollowsTheSeedScaling) {
  const std::string ex = root() + "/examples/mill";
  const auto dir = temp_dir("drive");
  CliResult c = run_nck("run " + ex + " " + ex + "/spindle.nc --trace " + (dir / "t.csv").string());
  ASSERT_EQ(c.exit_code, 0) << c.output;
  const auto lines = split(read_file(dir / "t.csv"), '\n');
  const auto header = split(lines[0], ',');
  const auto rpm = std::find(header.begin(), header.end(), "S2.rpm") - header.begin();
  const auto drive = std::find(header.begin(), header.end(), "S2.drive") - header.begin();
  ASSERT_LT(static_cast<std::size_t>(drive), header.size());
  bool seen = false;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto c2 = split(lines[i], ',');
    if (std::stod(c2[static_cast<std::size_t>(rpm)]) == -3000.0) {
      EXPECT_EQ(c2[static_cast<std::size_t>(drive)], "-32767");  // 3000 rpm <-> 32767
      seen = true;
    }
  }
  EXPECT_TRUE(seen);
}

TEST(SpindleScenario, SilentPlcEndsInATimeoutNotAHang) {
  const auto dir = temp_dir("silent");
  std::ofstream(dir / "silent.plc") << "0 silent on\n";
  RunResult r = run(root() + "/examples/mill", "%s\nN10 S1000 M3\nN20 G1 X10 F1000\nN30 M30\n",
              "--plc " + (dir / "silent.plc").string() + " --max-time 60");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const auto errors = of_kind(r.events, "error");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0]["id"], 960021);
  EXPECT_EQ(errors[0]["line"], 2);  // N10: its M3 waits for the PLC before any motion
  EXPECT_NEAR(errors[0]["t"].get<double>(), 2.0, 0.01);  // m3_prozess_zeit 2 s
}

TEST(SpindleScenario, BadSpindleInputIsAnNcErrorWithItsLine) {
  const std::string mill = root() + "/examples/mill";
  struct Case {
    const char* program;
    std::uint32_t id;
    int line;
  } cases[] = {
      {"%s\nN10 M19 S.POS=90\nN20 M30\n", 930101, 2},        // M19 without speed
      {"%s\nN10 S9[M3 REV100]\nN20 M30\n", 0, 2},             // unknown spindle (decoder)
      {"%s\nN10 S1000 M3 M4\nN20 M30\n", 0, 2},               // conflicting M functions
      {"%s\nN10 S2[M19 REV100 POS10]\nN20 M30\n", 70252, 2},  // sensorless S2 cannot position
  };
  for (const Case& c : cases) {
    RunResult r = run(mill, c.program);
    EXPECT_EQ(r.exit_code, 1) << c.program << r.output;
    const auto errors = of_kind(r.events, "error");
    ASSERT_FALSE(errors.empty()) << c.program;
    if (c.id != 0) {
      EXPECT_EQ(errors[0]["id"], c.id) << c.program;
    }
    EXPECT_EQ(errors[0]["line"], c.line) << c.program;
    EXPECT_EQ(of_kind(r.events, "end").size(), 1u);
  }
}

TEST(SpindleScenario, PreferredDirectionRejectsTheOtherOne) {
  const auto m = patched("mill", "pref", "s1.lis", "kenngr.vorz_richtung 1\nkenngr.beweg_richt 1\n");
  RunResult ok = run(m, "%s\nN10 S500 M3\nN20 M30\n");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  RunResult bad = run(m, "%s\nN10 S500 M4\nN20 M30\n");
  EXPECT_EQ(bad.exit_code, 1);
  const auto errors = of_kind(bad.events, "error");
  ASSERT_FALSE(errors.empty());
  EXPECT_EQ(errors[0]["id"], 60254);
}

TEST(SpindleScenario, ProgramEndKeepsRotationUnlessThePlcSaysStop) {
  const auto dir = temp_dir("end");
  std::ofstream(dir / "stop.plc") << "0 spindle_stop_at_end on S1\n";
  const std::string prog = "%s\nN10 S800 M3\nN20 G4 X0.5\nN30 M30\n";
  RunResult keep = run(root() + "/examples/mill", prog, "--final " + (dir / "keep.json").string());
  ASSERT_EQ(keep.exit_code, 0) << keep.output;
  EXPECT_EQ(json::parse(read_file(dir / "keep.json"))["spindles"]["S1"]["mode"], "rotate");
  RunResult stop = run(root() + "/examples/mill", prog,
                 "--plc " + (dir / "stop.plc").string() + " --final " + (dir / "stop.json").string());
  ASSERT_EQ(stop.exit_code, 0) << stop.output;
  EXPECT_EQ(json::parse(read_file(dir / "stop.json"))["spindles"]["S1"]["mode"], "stop");
}

// FCT-S1 2.7, examples 1-3: spindle homing never holds up the channel.
double spindle_homing_start(const std::vector<json>& events) {
  for (const json& e : events)
    if (e["ev"] == "spindle" && e["spindle"] == "S1" && e["mode"] == "homing") return e["t"];
  return -1;
}

TEST(SpindleScenario, HomingExamplesOfTheSeed) {
  const std::string mill = root() + "/examples/mill";
  const std::string start = "%h\nN5 G0 X100 Y80 Z10\n";
  // 1: spindle homing starts with the Y axis (order 1); X (order 2) follows.
  RunResult one = run(mill, start + "N10 G74 X2 Y1 S1\nN20 G0 X10\nN30 M30\n");
  ASSERT_EQ(one.exit_code, 0) << one.output;
  EXPECT_DOUBLE_EQ(spindle_homing_start(one.events), block_time(one.events, 10));
  // 2: the next block starts at once, X homes while the spindle does.
  RunResult two = run(mill, start + "N10 G74 S1\nN15 G74 X1 Y2\nN20 G0 X10\nN30 M30\n");
  ASSERT_EQ(two.exit_code, 0) << two.output;
  EXPECT_DOUBLE_EQ(block_time(two.events, 15), block_time(two.events, 10));
  EXPECT_DOUBLE_EQ(spindle_homing_start(two.events), block_time(two.events, 10));
  // 3: the axes first, then the spindle; the block after it does not wait.
  RunResult three = run(mill, start + "N10 G74 X1 Y2\nN15 G74 S1\nN20 G0 X10\nN30 M30\n");
  ASSERT_EQ(three.exit_code, 0) << three.output;
  EXPECT_GT(block_time(three.events, 15), block_time(three.events, 10) + 0.3);
  EXPECT_DOUBLE_EQ(spindle_homing_start(three.events), block_time(three.events, 15));
  EXPECT_DOUBLE_EQ(block_time(three.events, 20), block_time(three.events, 15));
}

TEST(SpindleScenario, PlcSpindleIsAcknowledgedByThePlc) {
  const std::string ex = root() + "/examples/two-channel";
  const auto dir = temp_dir("plcspindle");
  std::ofstream(dir / "a.nc") << "%a\nN10 S3[M3 REV1000]\nN20 G1 X10 F2000\nN30 M30\n";
  std::ofstream(dir / "b.nc") << "%b\nN10 G4 X0.1\nN20 M30\n";
  CliResult c = run_nck("run " + ex + " " + (dir / "a.nc").string() + " " + (dir / "b.nc").string() +
                        " --events " + (dir / "e.jsonl").string());
  ASSERT_EQ(c.exit_code, 0) << c.output;
  const auto events = read_jsonl(dir / "e.jsonl");
  const auto waits = of_kind(events, "wait");
  ASSERT_EQ(waits.size(), 1u);
  EXPECT_EQ(waits[0]["reason"], "plc_ack");  // only the PLC acknowledges a PLC spindle
  EXPECT_EQ(waits[0]["spindle"], "S3");
  EXPECT_EQ(of_kind(events, "plc_ack").size(), 1u);
}

TEST(SpindleScenario, ToolDynamicsLimitTheNextStart) {
  // tools.lis: wz[5] gives S1 (log_ax_nr_spdl 4) at most 500 rpm.
  RunResult r = run(root() + "/examples/mill",
                    "%t\nN10 D5\nN20 S1000 M3\nN30 M5\nN40 S[DEFAULT_DYNAMIC_DATA]\nN50 S1000 M3\nN60 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<double> rpm;
  for (const json& e : of_kind(r.events, "spindle"))
    if (e["mode"] == "rotate") rpm.push_back(e["rpm"]);
  ASSERT_EQ(rpm.size(), 2u);
  EXPECT_DOUBLE_EQ(rpm[0], 500.0);   // the tool's max_speed_mm_s
  EXPECT_DOUBLE_EQ(rpm[1], 1000.0);  // back to the axis data
}

TEST(SpindleScenario, ResetStopsSpindlesUnlessConfiguredToKeepThem) {
  const auto dir = temp_dir("reset");
  std::ofstream(dir / "reset.plc") << "0.5 reset\n";
  const std::string prog = "%r\nN10 S800 M3\nN20 G4 X2\nN30 M30\n";
  const std::string args = "--plc " + (dir / "reset.plc").string() + " --final ";
  RunResult stop = run(root() + "/examples/mill", prog, args + (dir / "a.json").string());
  EXPECT_EQ(stop.exit_code, 0) << stop.output;  // a reset is not an error
  ASSERT_EQ(of_kind(stop.events, "end").size(), 1u);
  EXPECT_EQ(of_kind(stop.events, "end")[0]["reason"], "reset");
  EXPECT_EQ(json::parse(read_file(dir / "a.json"))["spindles"]["S1"]["mode"], "stop");
  const auto keep_machine = patched("mill", "keep", "s1.lis", "kenngr.no_stop_by_channel_reset 1");
  RunResult keep = run(keep_machine, prog, args + (dir / "b.json").string());
  EXPECT_EQ(keep.exit_code, 0) << keep.output;
  EXPECT_EQ(json::parse(read_file(dir / "b.json"))["spindles"]["S1"]["mode"], "rotate");
}

TEST(SpindleScenario, MainSpindleCanBeChanged) {
  RunResult r = run(root() + "/examples/mill",
                    "%m\nN10 #MAIN SPINDLE [S2]\nN20 S500 M3\nN30 S1[M3 REV200]\nN40 #MAIN SPINDLE\nN50 S300\nN60 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<std::pair<std::string, double>> seen;
  for (const json& e : of_kind(r.events, "spindle")) seen.emplace_back(e["spindle"], e["rpm"]);
  ASSERT_GE(seen.size(), 3u);
  EXPECT_EQ(seen[0], (std::pair<std::string, double>{"S2", 500}));
  EXPECT_EQ(seen[1], (std::pair<std::string, double>{"S1", 200}));
  EXPECT_EQ(seen[2], (std::pair<std::string, double>{"S1", 300}));  // S is S1 again
}

TEST(SpindleScenario, GearErrorsOnTheLathe) {
  const std::string lathe = root() + "/examples/lathe";
  RunResult wrong = run(lathe, "%g\nN10 M40 S3000 M3\nN20 M30\n");  // stage 1 covers 20..800
  EXPECT_EQ(wrong.exit_code, 1) << wrong.output;
  ASSERT_FALSE(of_kind(wrong.events, "error").empty());
  EXPECT_EQ(of_kind(wrong.events, "error")[0]["line"], 2);
  RunResult high = run(lathe, "%g\nN10 S9000 M3\nN20 M30\n");  // no stage covers 9000
  EXPECT_EQ(high.exit_code, 1) << high.output;
  ASSERT_FALSE(of_kind(high.events, "error").empty());
  EXPECT_NE(of_kind(high.events, "error")[0]["id"], of_kind(wrong.events, "error")[0]["id"]);
}

TEST(SpindleScenario, ChannelPlcSpindleKnowsOnlySpeedAndSpindleM) {
  const auto m = patched("mill", "plcctl", "channel1.lis",
                         "spdl_anzahl 3\nspindel[2].bezeichnung S3\nspindel[2].log_achs_nr 9\n"
                         "spindel[2].plc_control 1\n");
  RunResult ok = run(m, "%p\nN10 S3[M3 REV700]\nN20 S3[M19 REV100 POS10]\nN30 M30\n");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_EQ(of_kind(ok.events, "plc_out").size(), 2u);
  RunResult bad = run(m, "%p\nN10 S3[G74]\nN20 M30\n");
  EXPECT_EQ(bad.exit_code, 1);
  ASSERT_FALSE(of_kind(bad.events, "error").empty());
  EXPECT_EQ(of_kind(bad.events, "error")[0]["id"], 930013);
}

// TF5200 HLI ext_to_ipo (docs/plc-scenario.md): external jobs run in order
// of arrival; the order holds per
// spindle, and a job to S1 does not wait until S2 has reached its speed.
TEST(SpindleScenario, ExternalCommandsKeepTheirOrderPerSpindleEachAcknowledged) {
  const auto dir = temp_dir("ext");
  std::ofstream(dir / "x.plc") << "0 spindle_cmd S2 M3 REV1500\n0 spindle_cmd S1 M4 REV300\n"
                                  "0 spindle_cmd S1 M19 POS90 REV100\n";
  RunResult r = run(root() + "/examples/mill", "%x\nN10 G4 X4\nN20 M30\n", "--plc " + (dir / "x.plc").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::map<std::string, double> ack_t;
  for (const json& e : of_kind(r.events, "plc_ack"))
    ack_t[e["spindle"].get<std::string>() + " " + e["fn"].get<std::string>()] = e["t"];
  ASSERT_EQ(ack_t.size(), 3u);
  std::map<std::string, double> start;
  for (const json& e : of_kind(r.events, "spindle")) start.try_emplace(e["spindle"].get<std::string>(), e["t"]);
  EXPECT_DOUBLE_EQ(start.at("S1"), start.at("S2"));  // S1 does not wait for S2's 1500 rpm
  // S1 at 300 rpm (1800 deg/s at 20000 deg/s^2: 0.09 s) is there before S2
  // at 1500 rpm (9000 deg/s at 30000 deg/s^2: 0.3 s).
  EXPECT_LT(ack_t.at("S1 M4"), ack_t.at("S2 M3"));
  EXPECT_LT(ack_t.at("S1 M4"), ack_t.at("S1 M19"));  // S1's own order holds
  double m19_start = -1;
  for (const json& e : of_kind(r.events, "spindle"))
    if (e["spindle"] == "S1" && e["mode"] != "rotate" && m19_start < 0) m19_start = e["t"];
  EXPECT_GE(m19_start, ack_t.at("S1 M4"));
}

TEST(SpindleScenario, HliPositionsFollowPStup00175) {
  const std::string prog = "%h\nN10 M19 S.POS=90 S100\nN20 G4 X0.5\nN30 M30\n";
  const auto dir = temp_dir("hli");
  RunResult r32 = run(root() + "/examples/mill", prog, "--final " + (dir / "a.json").string());
  ASSERT_EQ(r32.exit_code, 0) << r32.output;
  const json a = json::parse(read_file(dir / "a.json"))["hli"];
  EXPECT_EQ(a["position_format"], "32-bit, 0.0001 deg");
  EXPECT_NEAR(a["spindles"]["S1"]["actual_pos"].get<double>(), 900000, 2);  // 90 deg
  EXPECT_EQ(a["spindles"]["S1"]["mode_r"], 8);                               // M19
  const auto m64 = patched("mill", "hli64", "startup.lis", "ads_32_bit_comp_mode 0");
  RunResult r64 = run(m64, prog, "--final " + (dir / "b.json").string());
  ASSERT_EQ(r64.exit_code, 0) << r64.output;
  const json b = json::parse(read_file(dir / "b.json"))["hli"];
  EXPECT_EQ(b["position_format"], "64-bit, 1e-7 deg");
  EXPECT_NEAR(b["spindles"]["S1"]["actual_pos"].get<double>(), 900000000, 2000);
}

TEST(FitCurve, ReproducesTheSeedCoefficients) {
  const std::string pts = " --n-grenz 12000 --a-konst 16000 --point 24000,8000 --point 36000,4000 --point 48000,2000";
  CliResult poly = run_nck("fit-curve polynomial" + pts);
  ASSERT_EQ(poly.exit_code, 0) << poly.output;
  auto value = [](const std::string& out, const std::string& key) {
    const auto p = out.find(key + " ");
    return p == std::string::npos ? 0.0 : std::stod(out.substr(p + key.size() + 1));
  };
  EXPECT_NEAR(value(poly.output, "b3"), -1.92901234E-10, 1e-18);
  EXPECT_NEAR(value(poly.output, "b2"), 2.08333333E-5, 1e-13);
  EXPECT_NEAR(value(poly.output, "b1"), -0.88888888, 1e-8);
  CliResult hyp = run_nck("fit-curve hyperbola --n-grenz 12000 --a-konst 16000 --point 24000,8000 --point 36000,4000");
  ASSERT_EQ(hyp.exit_code, 0) << hyp.output;
  EXPECT_NEAR(value(hyp.output, "b2"), 0.4166666, 1e-6);
  EXPECT_NEAR(value(hyp.output, "b3"), 0.02857142, 1e-7);
  EXPECT_NEAR(value(hyp.output, "b1"), 22857.14, 0.01);
  EXPECT_EQ(run_nck("fit-curve polynomial --n-grenz 12000 --a-konst 16000 --point x").exit_code, 2);
}

}  // namespace
}  // namespace nck::app
