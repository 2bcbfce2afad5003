// Spindle behaviour through `nck run` on the mill example (positioning,
// tool speed limits, PLC spindles, acknowledgements, gear reverse, HLI
// objects): numbers from the seed FCT-S1 or computed by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

struct SpindleRunResult {
  int exit_code = -1;
  std::string output;
  std::vector<json> events;
  std::filesystem::path dir;
  json final_state;
  // column name -> values of every traced cycle
  std::map<std::string, std::vector<double>> trace;
};

std::map<std::string, std::vector<double>> read_trace(const std::filesystem::path& csv) {
  std::map<std::string, std::vector<double>> cols;
  const auto lines = split(read_file(csv), '\n');
  if (lines.empty()) return cols;
  const auto header = split(lines[0], ',');
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto cells = split(lines[i], ',');
    for (std::size_t j = 0; j < cells.size() && j < header.size(); ++j)
      if (!cells[j].empty()) cols[header[j]].push_back(std::stod(cells[j]));
  }
  return cols;
}

// Runs `program_text` on `machine` with events, an every-cycle trace and --final.
SpindleRunResult run(const std::filesystem::path& machine, const std::string& program_text, const std::string& args = "") {
  SpindleRunResult r;
  r.dir = temp_dir("review");
  std::ofstream(r.dir / "p.nc") << program_text;
  const CliResult c = run_nck("run " + machine.string() + " " + (r.dir / "p.nc").string() + " --events " +
                              (r.dir / "e.jsonl").string() + " --trace " + (r.dir / "t.csv").string() +
                              " --final " + (r.dir / "f.json").string() + " " + args);
  r.exit_code = c.exit_code;
  r.output = c.output;
  r.events = read_jsonl(r.dir / "e.jsonl");
  const std::string final_text = read_file(r.dir / "f.json");
  if (!final_text.empty()) r.final_state = json::parse(final_text);
  r.trace = read_trace(r.dir / "t.csv");
  return r;
}



std::filesystem::path mill_with(const std::string& name, const std::string& file, const std::string& lines) {
  return patched_example("mill", name, file, lines).dir;
}

std::vector<json> of_kind(const std::vector<json>& events, const std::string& ev, const std::string& spindle) {
  std::vector<json> out;
  std::copy_if(events.begin(), events.end(), std::back_inserter(out),
               [&](const json& e) { return e["ev"] == ev && e.value("spindle", json()) == spindle; });
  return out;
}

std::vector<std::string> modes(const std::vector<json>& events, const std::string& spindle) {
  std::vector<std::string> out;
  for (const json& e : of_kind(events, "spindle", spindle)) out.push_back(e["mode"]);
  return out;
}

// Item 3, seed 2.3.2 "distance optimisation from standstill": from 0 deg the
// shorter way to 350 deg is -10 deg, also when the first M19 homes first.
TEST(SpindleRun, M19FromStandstillTakesTheShorterWayAlsoWhenItHomesFirst) {
  const SpindleRunResult r = run(mill(), "%a\nN10 M19 S.POS=350 S100\nN20 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto& rpm = r.trace.at("S1.rpm");
  EXPECT_LT(*std::min_element(rpm.begin(), rpm.end()), 0.0);
  EXPECT_LE(*std::max_element(rpm.begin(), rpm.end()), 0.0);  // never the long way round (+350)
  EXPECT_NEAR(r.final_state["spindles"]["S1"]["pos"].get<double>(), 350.0, 0.01);
  EXPECT_TRUE(r.final_state["spindles"]["S1"]["homed"].get<bool>());
  // -10 deg at 100 rpm (600 deg/s) plus settling into the window, well
  // below the 0.58 s that +350 deg alone would take.
  EXPECT_LT(r.final_state["time"].get<double>(), 0.5);
}

// Item 8: kenngr.achs_mode 0x100 (ACHSMODE_KEINE_AUTO_RPF): no automatic
// homing before M19 (seed 2.7: digital drives home with G74 only).
TEST(SpindleRun, AchsModeKeineAutoRpfPositionsWithoutHoming) {
  const SpindleRunResult plain = run(mill(), "%b\nN10 M19 S.POS=90 S100\nN20 M30\n");
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_TRUE(plain.final_state["spindles"]["S1"]["homed"].get<bool>());  // the default homes first
  const SpindleRunResult r = run(mill_with("noautorpf", "s1.lis", "kenngr.achs_mode 0x00000104"),
                    "%b\nN10 M19 S.POS=90 S100\nN20 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto m = modes(r.events, "S1");
  EXPECT_EQ(std::count(m.begin(), m.end(), "homing"), 0) << r.output;
  EXPECT_EQ(m.front(), "position");
  EXPECT_NEAR(r.final_state["spindles"]["S1"]["pos"].get<double>(), 90.0, 0.01);
  EXPECT_FALSE(r.final_state["spindles"]["S1"]["homed"].get<bool>());
}

// Item 10, seed 2.8.5: the tool's minimum speed limits endless turning only.
// Tool 5 (tools.lis) gives S1 vb_min 10 rpm; M19 at 5 rpm stays at 5 rpm.
TEST(SpindleRun, ToolMinimumSpeedLimitsOnlyEndlessTurning) {
  const SpindleRunResult r = run(mill(), "%c\nN10 D5\nN20 M19 S.POS=90 S5\nN30 S5 M3\nN40 G4 X0.2\nN50 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<double> rotate_rpm;
  for (const json& e : of_kind(r.events, "spindle", "S1"))
    if (e["mode"] == "rotate") rotate_rpm.push_back(e["rpm"]);
  ASSERT_EQ(rotate_rpm.size(), 1u);
  EXPECT_DOUBLE_EQ(rotate_rpm[0], 10.0);  // M3 S5 is raised to the tool's 10 rpm
  // Up to the M3 block the spindle positions at 5 rpm (90 deg at 30 deg/s: 3 s).
  const auto& t = r.trace.at("t");
  const auto& rpm = r.trace.at("S1.rpm");
  double m19_peak = 0;
  for (std::size_t i = 0; i < t.size() && t[i] < 2.5; ++i) m19_peak = std::max(m19_peak, std::fabs(rpm[i]));
  EXPECT_NEAR(m19_peak, 5.0, 1e-9);
}

// Item 6: a PLC spindle over the channel HLI has no axis list, so no NC
// speed limit: 700 rpm stays 700 rpm (not the default max_speed_mm_s 33.3 rpm).
TEST(SpindleRun, ChannelPlcSpindleIsNotClampedToTheDefaultVbMax) {
  const auto m = mill_with("plcnolimit", "channel1.lis",
                           "spdl_anzahl 3\nspindel[2].bezeichnung S3\nspindel[2].log_achs_nr 9\n"
                           "spindel[2].plc_control 1\n");
  // Default acceleration 1000 deg/s^2: 700 rpm (4200 deg/s) after 4.2 s.
  const SpindleRunResult r = run(m, "%d\nN10 S3[M3 REV700]\nN20 G4 X5\nN30 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("950007"), std::string::npos) << r.output;
  const auto ev = of_kind(r.events, "spindle", "S3");
  ASSERT_FALSE(ev.empty());
  EXPECT_DOUBLE_EQ(ev.front()["rpm"].get<double>(), 700.0);
  EXPECT_NEAR(r.final_state["spindles"]["S3"]["rpm"].get<double>(), 700.0, 1e-6);
}

// Item 12, seed 2.2.4 (case 3): a sensorless spindle acknowledges the speed
// from its internal command value. S2 ramps at 30000 deg/s^2: 900 rpm (the
// -10 % edge of 1000 rpm) = 5400 deg/s after 0.18 s; the simulated actual
// (20 ms lag) would need 0.2 s.
TEST(SpindleRun, SensorlessSpindleAcknowledgesFromTheInternalCommandValue) {
  const SpindleRunResult r = run(mill(), "%e\nN10 S2[M3 REV1000]\nN20 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto start = of_kind(r.events, "spindle", "S2");
  const auto reached = of_kind(r.events, "speed_reached", "S2");
  ASSERT_FALSE(start.empty());
  ASSERT_EQ(reached.size(), 1u);
  EXPECT_NEAR(reached[0]["t"].get<double>() - start[0]["t"].get<double>(), 0.18, 0.0015);
}

// Item 13, P-AXIS-00159 getriebe[i].reverse: the drive value goes out with
// the other sign (M3 3000 rpm -> -32767, seed 2.2.4.1 scaling) and the actual
// comes back flipped again, so the NC still sees M3 and reaches its speed.
TEST(SpindleRun, GearReverseInvertsDriveValueAndActualValues) {
  const auto m = mill_with("reverse", "s2.lis", "getriebe[0].reverse 1");
  const SpindleRunResult r = run(m, "%f\nN10 S2[M3 REV3000]\nN20 G4 X0.5\nN30 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto& rpm = r.trace.at("S2.rpm");
  const auto& drive = r.trace.at("S2.drive");
  const auto& act = r.trace.at("S2.act_rpm");
  bool seen = false;
  for (std::size_t i = 0; i < rpm.size(); ++i)
    if (rpm[i] == 3000.0) {
      EXPECT_EQ(drive[i], -32767.0);
      EXPECT_GT(act[i], 0.0);
      seen = true;
    }
  EXPECT_TRUE(seen);
  EXPECT_EQ(of_kind(r.events, "speed_reached", "S2").size(), 1u);
  // A position-controlled spindle with reverse still positions exactly.
  const SpindleRunResult p = run(mill_with("reverse1", "s1.lis", "getriebe[0].reverse 1"), "%f\nN10 M19 S.POS=90 S100\nN20 M30\n");
  ASSERT_EQ(p.exit_code, 0) << p.output;
  EXPECT_NEAR(p.final_state["hli"]["spindles"]["S1"]["actual_pos"].get<double>(), 900000, 100);
}

// Item 14, seed 2.3: a conflicting direction (60254) puts the spindle into
// error state; the events and the final state of the aborted run show it.
TEST(SpindleRun, PreferredDirectionErrorStateIsVisibleAfterTheAbort) {
  const auto m = mill_with("errstate", "s1.lis", "kenngr.vorz_richtung 1\nkenngr.beweg_richt 1\n");
  const SpindleRunResult r = run(m, "%g\nN10 S500 M4\nN20 M30\n");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(modes(r.events, "S1"), (std::vector<std::string>{"error"}));
  EXPECT_EQ(std::count_if(r.events.begin(), r.events.end(), [](const json& e) { return e["ev"] == "error"; }), 1);
  EXPECT_EQ(r.final_state["spindles"]["S1"]["mode"], "error");
  EXPECT_TRUE(r.final_state["hli"]["spindles"]["S1"]["command_error"].get<bool>());
}

// Item 15, seed 2.9: --final lists the spindle's HLI objects, named after
// their TF5200 HLI paths. 200 rpm = 1200 deg/s = 1200000 in 0.001 deg/s.
TEST(SpindleRun, FinalStateListsTheSeedsHliSpindleObjects) {
  const SpindleRunResult rot = run(mill(), "%h\nN10 S200 M3\nN20 G4 X0.5\nN30 M30\n");
  ASSERT_EQ(rot.exit_code, 0) << rot.output;
  const json& a = rot.final_state["hli"]["spindles"]["S1"];
  EXPECT_EQ(a["cmd_rev_r"], 1200000);
  EXPECT_EQ(a["rev_control_aktiv_r"], true);
  EXPECT_EQ(a["speed_monitoring_invalid"], false);
  EXPECT_EQ(a["command_error"], false);
  EXPECT_EQ(a["distance_to_go"], 0);
  // M19 at 10 rpm (60 deg/s) to 180 deg, stopped after 1 s: about 120 deg to go.
  const SpindleRunResult pos = run(mill(), "%h\nN10 M19 S.POS=180 S10\nN20 M30\n", "--max-time 1");
  EXPECT_EQ(pos.exit_code, 1) << pos.output;
  const json& b = pos.final_state["hli"]["spindles"]["S1"];
  EXPECT_EQ(b["target_pos"], 1800000);
  EXPECT_NEAR(b["distance_to_go"].get<double>(), 1200000, 2000);
  EXPECT_EQ(b["rev_control_aktiv_r"], false);
}

}  // namespace
}  // namespace nck::app
