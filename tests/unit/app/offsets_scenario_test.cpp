// examples/mill/offsets.nc through `nck run`: the machine position at the
// end of each block, computed by hand from zero.lis (G54 X100 Y50 Z-150),
// tools.lis (D1 length 100) and the program's own offsets.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

struct Row {
  double x, y, z;
};

TEST(OffsetsScenario, MachinePositionsAtBlockEndsMatchHandComputation) {
  const auto dir = temp_dir("offsets");
  CliResult r = run_example("mill", "offsets.nc", dir, "--final " + (dir / "f.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto at_block_start = positions_at_blocks(dir);
  const double s = std::sqrt(0.5) * 20;  // 20 mm at 45 degrees
  const std::map<long, Row> expected = {
      {50, {100, 50, 0}},          // after N40: G54 + D1 + Z50
      {70, {110, 50, 0}},          // after N60: G92 X10
      {90, {100, 50, 0}},          // after N80: G92 off
      {110, {120, 60, 0}},         // after N100: CS shift 20, turned 90 deg
      {120, {110, 50, 0}},         // after N110: circle end (0,10) in the CS
      {150, {100 + s, 50 + s, 0}}, // after N140: #ROTATION 45 deg
      {170, {100, 50, 0}},         // after N160
      {190, {110, 50, 0}},         // after N180: #PSET X5, then X15
      {210, {0, 0, 0}},            // after N200: G54 suppressed, tool on Z only
  };
  for (const auto& [n, want] : expected) {
    ASSERT_TRUE(at_block_start.count(n)) << "N" << n;
    const auto& got = at_block_start.at(n);
    EXPECT_NEAR(got[0], want.x, 1e-6) << "before N" << n;
    EXPECT_NEAR(got[1], want.y, 1e-6) << "before N" << n;
    EXPECT_NEAR(got[2], want.z, 1e-6) << "before N" << n;
  }
  // offset events name each kind the program changed
  std::set<std::string> kinds;
  for (const json& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "offset") kinds.insert(e["kind"].get<std::string>());
  for (const char* k : {"zero", "tool", "g92", "cs", "rotation", "pset"}) EXPECT_TRUE(kinds.count(k)) << k;
  const json fin = json::parse(read_file(dir / "f.json"));
  EXPECT_NEAR(fin["channels"][0]["axes"]["X"]["pcs"].get<double>(), 0.0, 1e-9);
}

TEST(OffsetsScenario, ClampIndexShiftsEveryPathAxisFromTheStart) {
  const auto dir = temp_dir("clamp");
  const auto prog = dir / "p.nc";
  std::ofstream(prog) << "%p\nN10 G0 X0 Y0 Z0\nN20 M30\n";
  const std::string ex = root() + "/examples/mill";
  CliResult r = run_nck("run " + ex + " " + prog.string() + " --clamp-index 1 --final " + (dir / "f.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json fin = json::parse(read_file(dir / "f.json"));
  // clamp.lis group 1: X +10 mm, Y -5 mm
  EXPECT_NEAR(fin["channels"][0]["axes"]["X"]["mcs"].get<double>(), 10.0, 1e-9);
  EXPECT_NEAR(fin["channels"][0]["axes"]["Y"]["mcs"].get<double>(), -5.0, 1e-9);
  EXPECT_NEAR(fin["channels"][0]["axes"]["X"]["pcs"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(fin["channels"][0]["offsets"]["clamp"]["X"].get<double>(), 10.0, 1e-9);
}


TEST(MeasureScenario, G100StopsAtTheProbeAndG101OffsetsByTheDifference) {
  const auto dir = temp_dir("measure");
  CliResult r = run_example("mill", "measure.nc", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto p = positions_at_blocks(dir);
  EXPECT_NEAR(p.at(20)[2], -100.0, 1e-9);  // G54 Z-150 + D1 100 + PCS -50
  EXPECT_NEAR(p.at(40)[2], -123.0, 1e-9);  // the probe switched at machine Z -123
  EXPECT_NEAR(p.at(60)[2], -116.0, 1e-9);  // PCS -73 plus the 7 mm measuring offset
  bool measure_event = false;
  for (const json& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "offset" && e["kind"] == "measure" && e["values"]["Z"] == 7.0) measure_event = true;
  EXPECT_TRUE(measure_event);
}

TEST(MeasureScenario, NoSwitchingMeansMerf0AndTheTargetReached) {
  const auto dir = temp_dir("nomeasure");
  std::ofstream(dir / "p.nc") << "%m\nN10 G0 X0 Y0 Z0\nN20 G100 Z-10 F600\nN30 P1 = V.A.MERF.Z\n"
                                 "$IF P1 == 0\nN40 G0 Z5\n$ENDIF\nN50 M30\n";
  std::ofstream(dir / "e.jsonl");
  CliResult r = run_nck("run " + root() + "/examples/mill " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string() + " --trace " + (dir / "t.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(positions_at_blocks(dir).at(40)[2], -10.0, 1e-9);  // target reached; V.A.MERF.Z = 0 chose N40
}

TEST(MeasureScenario, G101WithNothingMeasuredIsAnError) {
  const auto dir = temp_dir("g101");
  std::ofstream(dir / "p.nc") << "%m\nN10 G0 Z0\nN20 G101 Z1\nN30 M30\n";
  CliResult r = run_nck("run " + root() + "/examples/mill " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  bool found = false;
  for (const json& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "error" && e["line"] == 3) found = true;
  EXPECT_TRUE(found) << r.output;
}


json run_manual(const std::string& name, const std::string& scenario) {
  const auto dir = temp_dir(name);
  std::ofstream(dir / "s.plc") << scenario;
  const std::string ex = root() + "/examples/mill";
  CliResult r = run_nck("run " + ex + " " + ex + "/manual.nc --plc " + (dir / "s.plc").string() +
                        " --final " + (dir / "f.json").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return json::parse(read_file(dir / "f.json"));
}

TEST(ManualScenario, HandwheelOffsetActsInG201AndReachesTheProgram) {
  const json fin = run_manual("manual", "0.5 handwheel X 1.5\n");
  // #GET MANUAL OFFSETS gave 1.5 -> the program moved to X3; the offset stays: MCS 4.5
  EXPECT_NEAR(fin["channels"][0]["axes"]["X"]["pcs"].get<double>(), 3.0, 1e-9);
  EXPECT_NEAR(fin["channels"][0]["axes"]["X"]["mcs"].get<double>(), 4.5, 1e-9);
  EXPECT_NEAR(fin["channels"][0]["offsets"]["manual"]["X"].get<double>(), 1.5, 1e-9);
}

TEST(ManualScenario, HandwheelOutsideManualModeDoesNothing) {
  const json fin = run_manual("nomanual", "0.5 handwheel Y 2\n2.5 handwheel X 1\n");  // Y not in G201; X after G202
  EXPECT_NEAR(fin["channels"][0]["axes"]["X"]["mcs"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(fin["channels"][0]["axes"]["Y"]["mcs"].get<double>(), 0.0, 1e-9);
}


struct Outcome {
  int exit_code;
  std::vector<json> events;
  json final_state;
};

Outcome run_program(const std::string& name, const std::string& blocks, const std::string& args = "") {
  const auto dir = temp_dir(name);
  std::ofstream(dir / "p.nc") << "%p\n" << blocks << "N90 M30\n";
  CliResult r = run_nck("run " + root() + "/examples/mill " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string() + " --final " + (dir / "f.json").string() + " " + args);
  return {r.exit_code, read_jsonl(dir / "e.jsonl"), json::parse(read_file(dir / "f.json"))};
}

TEST(OffsetErrors, EachIsAnNcErrorWithItsIdAndLine) {
  struct Case {
    const char* blocks;
    std::uint32_t id;
    int line;
  } cases[] = {
      {"N10 #CS ON [1][10,0,0,0,0,0]\nN20 #ECS ON\n", 20774, 3},   // #ECS with a CS active
      {"N10 #PSET X5 G1 Y10 F100\n", 20607, 2},                    // #PSET with a path condition
      {"N10 G159=99\n", 20149, 2},                                 // beyond the zero table
      {"N10 #CS ON [3]\n", 970002, 2},                             // never defined
      {"N10 #CS ON [1,0,0]\nN11 #CS ON [1,0,0]\nN12 #CS ON [1,0,0]\nN13 #CS ON [1,0,0]\n"
       "N14 #CS ON [1,0,0]\nN15 #CS ON [1,0,0]\n", 970003, 7},    // more than 5 nested
      {"N10 #SUPPRESS OFFSETS G91 X1\n", 20985, 2},                // needs G90
      {"N10 D42\n", 930011, 2},                                    // not in the tool list
  };
  for (const Case& c : cases) {
    Outcome o = run_program("ofserr", c.blocks);
    EXPECT_EQ(o.exit_code, 1) << c.blocks;
    const json* err = nullptr;
    for (const json& e : o.events)
      if (e["ev"] == "error" && !err) err = &e;
    ASSERT_NE(err, nullptr) << c.blocks;
    EXPECT_EQ((*err)["id"], c.id) << c.blocks;
    EXPECT_EQ((*err)["line"], c.line) << c.blocks;
    ASSERT_EQ(o.events.back()["ev"], "end");  // the events file is complete
  }
}

TEST(OffsetErrors, PlaneChangeSwitchesRotationOffWithWarning21143) {
  Outcome o = run_program("w21143", "N10 #ROTATION ON [ANGLE=10]\nN20 G18\n");
  EXPECT_EQ(o.exit_code, 0);
  bool warned = false;
  for (const json& e : o.events)
    if (e["ev"] == "warning" && e["id"] == 21143 && e["line"] == 3) warned = true;
  EXPECT_TRUE(warned);
}

TEST(OffsetVariables, ProgramReadsTheZeroTableAndTheClampPosition) {
  Outcome o = run_program("vars", "N10 G54\nN20 P1 = V.G.NP[1].V.X\nN25 P2 = V.G.AKT_PLATZ\nN30 G0 X[P1 + P2]\n",
                          "--clamp-index 1");
  ASSERT_EQ(o.exit_code, 0);
  const json& x = o.final_state["channels"][0]["axes"]["X"];
  EXPECT_NEAR(x["pcs"].get<double>(), 101.0, 1e-9);        // 100 (G54 X) + 1 (clamp index)
  EXPECT_NEAR(x["mcs"].get<double>(), 101.0 + 100 + 10, 1e-9);  // + G54 + clamp group 1
}

TEST(OffsetVariables, WritingTheZeroTableMovesTheNextAbsolutePosition) {
  Outcome o = run_program("npwrite", "N10 G54 G0 X0\nN20 V.G.NP[1].V.X = 20\nN30 G0 X0\n");
  ASSERT_EQ(o.exit_code, 0);
  EXPECT_NEAR(o.final_state["channels"][0]["axes"]["X"]["mcs"].get<double>(), 20.0, 1e-9);
}


TEST(CoordinatesScenario, CsChainAcsAndMcsMatchHandComputation) {
  const auto dir = temp_dir("coordinates");
  ASSERT_EQ(run_example("mill", "coordinates.nc", dir).exit_code, 0);
  const auto p = positions_at_blocks(dir);
  const double c = std::cos(2 * M_PI / 180), s = std::sin(2 * M_PI / 180);
  // HOLE X10 Y0 -> PART (5,5)+R90(10,0) = (5,15) -> ACS (25,25) turned 2 deg, + G54
  EXPECT_NEAR(p.at(70)[0], 100 + 25 * c - 25 * s, 1e-6);
  EXPECT_NEAR(p.at(70)[1], 50 + 25 * s + 25 * c, 1e-6);
  // PART X0 Y0 -> ACS (20,10) turned 2 deg, + G54
  EXPECT_NEAR(p.at(90)[0], 100 + 20 * c - 10 * s, 1e-6);
  EXPECT_NEAR(p.at(90)[1], 50 + 20 * s + 10 * c, 1e-6);
  EXPECT_NEAR(p.at(110)[2], 0.0, 1e-9);    // #MCS ON: machine Z0
  EXPECT_NEAR(p.at(130)[2], -100.0, 1e-9); // #MCS OFF restored G54: -150 + 50
  EXPECT_NEAR(p.at(160)[0], 100.0, 1e-9);  // all CS off: G54 only
}

TEST(ToolsScenario, ToolLengthG91RuleAndTlc) {
  const auto dir = temp_dir("tools");
  ASSERT_EQ(run_example("mill", "tools.nc", dir).exit_code, 0);
  const auto p = positions_at_blocks(dir);
  EXPECT_NEAR(p.at(40)[2], 100.0, 1e-9);  // D1 (100 mm) at the absolute Z0
  EXPECT_NEAR(p.at(60)[2], 90.0, 1e-9);   // G91: D2 waits, Z moved -10
  EXPECT_NEAR(p.at(70)[2], 115.0, 1e-9);  // absolute Z-10 with D2 (125 mm)
  EXPECT_NEAR(p.at(90)[2], 115.5, 1e-9);  // #TLC ON [0.5]
  EXPECT_NEAR(p.at(110)[2], 0.0, 1e-9);   // D0
}


// P-CHAN-00100: 0 (mill default) moves a new tool length at the next absolute
// position; 1 moves it with the D word.
TEST(ToolsScenario, MoveToolOffsetsDirectly) {
  const auto machine = patched_example("mill", "direct", "channel1.lis", "move_tool_offsets_directly 1").dir;
  const auto dir = machine.parent_path();
  std::ofstream(dir / "p.nc") << "%d\nN10 G0 X0 Y0 Z0\nN20 D1\nN30 G0 X10\nN40 M30\n";
  CliResult r = run_nck("run " + machine.string() + " " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string() + " --trace " + (dir / "t.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto p = positions_at_blocks(dir);
  EXPECT_NEAR(p.at(30)[2], 100.0, 1e-9);  // the D1 block itself moved Z by the tool length
  EXPECT_NEAR(p.at(30)[0], 0.0, 1e-9);
}

}  // namespace
}  // namespace nck::app
