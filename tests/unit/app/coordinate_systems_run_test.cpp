// Coordinate systems, presets, handwheel offsets and offset variables
// through `nck run` on examples/mill
// (zero.lis: G54 X100 Y50 Z-150, G55 X200 Y100 Z-150; tools.lis: D1 100 mm).
// Every expected machine position is computed by hand in the comment beside it.
#include <gtest/gtest.h>

#include <map>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

struct ProgramRun {
  std::filesystem::path dir;
  int exit_code = -1;
  std::string output;
  std::map<long, std::array<double, 3>> at_block;  // X Y Z when block N starts
  std::vector<json> events;
  json final_state;
};

// `blocks` must end with a numbered block after the last move (its start is
// where the move ended) and M30.
ProgramRun run_blocks(const std::string& name, const std::string& blocks, const std::string& args = "") {
  const auto dir = temp_dir(name);
  // G360: every block ends at standstill, so the trace shows its end point
  // when the next one starts (at_block).
  std::ofstream(dir / "p.nc") << "%p\nG360\n" << blocks;
  const std::string ex = root() + "/examples/mill";
  CliResult r = run_nck("run " + ex + " " + (dir / "p.nc").string() + " --events " + (dir / "e.jsonl").string() +
                        " --trace " + (dir / "t.csv").string() + " --final " + (dir / "f.json").string() + " " +
                        args);
  ProgramRun out{dir, r.exit_code, r.output, {}, read_jsonl(dir / "e.jsonl"), json::parse(read_file(dir / "f.json"))};
  if (r.exit_code == 0) out.at_block = positions_at_blocks(dir);
  return out;
}

const json& channel(const ProgramRun& r) { return r.final_state["channels"][0]; }

// Item 16. Seed 2.2.1 / 2.2.3 / 2.2.6: zero offsets programmed while a CS
// (ACS, MCS) is active are valid only until it is deselected. Selecting one
// again afterwards must act, although the decoder's modal code never changed.
TEST(CoordinateSystemsRun, ZeroOffsetSelectedAgainAfterCsOffActs) {
  ProgramRun r = run_blocks("zo_cs", "N10 G54 G0 X0 Y0 Z0\nN20 #CS ON [0,0,0,0,0,0]\nN30 G55 G0 X0\nN40 #CS OFF\n"
                              "N50 G0 X0\nN60 G55 G0 X0\nN70 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(r.at_block.at(40)[0], 200.0, 1e-9);  // G55 inside the CS: X 200
  EXPECT_NEAR(r.at_block.at(60)[0], 100.0, 1e-9);  // #CS OFF put G54 back: X 100
  EXPECT_NEAR(r.at_block.at(70)[0], 200.0, 1e-9);  // G55 selected again: X 200
  EXPECT_EQ(channel(r)["modal"]["zero_offset"], "G55");
}

TEST(CoordinateSystemsRun, G53SelectedAgainAfterAcsOffActs) {
  ProgramRun r = run_blocks("zo_acs", "N10 G54 G0 X0 Y0 Z0\nN20 #ACS ON [0,0,0,0,0,0]\nN30 G53 G0 X0\nN40 #ACS OFF\n"
                               "N50 G0 X0\nN60 G53 G0 X0\nN70 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(r.at_block.at(40)[0], 0.0, 1e-9);    // G53 inside the ACS: no offset
  EXPECT_NEAR(r.at_block.at(60)[0], 100.0, 1e-9);  // #ACS OFF put G54 back
  EXPECT_NEAR(r.at_block.at(70)[0], 0.0, 1e-9);    // G53 selected again
  EXPECT_EQ(channel(r)["modal"]["zero_offset"], "G53");
}

TEST(CoordinateSystemsRun, ZeroOffsetSelectedAgainAfterMcsOffActs) {
  ProgramRun r = run_blocks("zo_mcs", "N10 G54 G0 X0 Y0 Z0\nN20 #MCS ON\nN30 G55 G0 X0\nN40 #MCS OFF\n"
                               "N50 G0 X0\nN60 G55 G0 X0\nN70 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(r.at_block.at(40)[0], 200.0, 1e-9);  // temporary G55 inside the MCS
  EXPECT_NEAR(r.at_block.at(60)[0], 100.0, 1e-9);  // #MCS OFF restored G54
  EXPECT_NEAR(r.at_block.at(70)[0], 200.0, 1e-9);
}

// --final names the zero offset in force, not the decoder's last modal code.
TEST(CoordinateSystemsRun, FinalReportsTheZeroOffsetInForceAfterCsOff) {
  ProgramRun r = run_blocks("zo_final", "N10 G54 G0 X0 Y0 Z0\nN20 #CS ON [0,0,0,0,0,0]\nN30 G55 G0 X0\nN40 #CS OFF\n"
                                 "N50 G0 X0\nN60 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(channel(r)["modal"]["zero_offset"], "G54");
  EXPECT_NEAR(channel(r)["offsets"]["zero"]["X"].get<double>(), 100.0, 1e-9);
}

// Item 17. Seed 2.5 (Istwertverschiebung): #PSET gives the current axis
// position a new value in program coordinates, so the tool length (machining
// directions, tool_fixed 0) and an active #CS stay out of the preset.
TEST(CoordinateSystemsRun, PsetKeepsTheToolLength) {
  ProgramRun r = run_blocks("pset_tool", "N10 D1 G0 X0 Y0 Z0\nN20 #PSET Z0\nN30 G0 Z10\nN40 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(r.at_block.at(20)[2], 100.0, 1e-9);  // Z0 + D1 100
  EXPECT_NEAR(r.at_block.at(40)[2], 110.0, 1e-9);  // the preset is 0: Z10 + 100
}

TEST(CoordinateSystemsRun, PsetInsideACsKeepsTheCsShift) {
  ProgramRun r = run_blocks("pset_cs", "N10 G0 X0 Y0 Z0\nN20 #CS ON [10,0,0,0,0,0]\nN30 G0 X0\nN40 #PSET X0\n"
                                "N50 G0 X5\nN60 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(r.at_block.at(40)[0], 10.0, 1e-9);  // CS X0 = machine 10
  EXPECT_NEAR(r.at_block.at(60)[0], 15.0, 1e-9);  // X0 already read 0: X5 = 10 + 5
}

TEST(CoordinateSystemsRun, PsetStillShiftsByTheDifference) {
  ProgramRun r = run_blocks("pset_shift", "N10 D1 G0 X0 Y0 Z0\nN20 #PSET Z20\nN30 G0 Z0\nN40 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(r.at_block.at(40)[2], 80.0, 1e-9);  // machine 100 reads Z20: Z0 is 20 lower
}

// Item 19. Seed 2.10: #SUPPRESS OFFSETS without kinds leaves out every
// offset, the handwheel's too; seed 2.2.6: #MCS ON removes every offset
// included in the axes. The handwheel adds X +1.5 in G201 (manual.plc style).
TEST(CoordinateSystemsRun, SuppressOffsetsAndMcsLeaveOutTheHandwheelOffset) {
  const auto plc = temp_dir("hw_plc") / "s.plc";
  std::ofstream(plc) << "0.5 handwheel X 1.5\n";
  ProgramRun r = run_blocks("hw_suppress",
                     "N10 G0 X0 Y0 Z0\nN20 G201 X1\nN30 G4 X2\nN40 G202\nN50 G0 X10\n"
                     "N60 #SUPPRESS OFFSETS X20\nN70 G0 X30\nN80 #MCS ON\nN90 G0 X40\nN100 #MCS OFF\n"
                     "N110 G0 X50\nN120 #SUPPRESS OFFSETS [ZERO] X60\nN130 #SUPPRESS OFFSETS [MANUAL] X70\n"
                     "N140 G0 X80\nN150 M30\n",
                     "--plc " + plc.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(r.at_block.at(60)[0], 11.5, 1e-9);   // X10 + handwheel 1.5
  EXPECT_NEAR(r.at_block.at(70)[0], 20.0, 1e-9);   // all offsets suppressed: machine X20
  EXPECT_NEAR(r.at_block.at(80)[0], 31.5, 1e-9);   // back at the next absolute X
  EXPECT_NEAR(r.at_block.at(100)[0], 40.0, 1e-9);  // #MCS: machine X40
  EXPECT_NEAR(r.at_block.at(120)[0], 51.5, 1e-9);  // after #MCS OFF
  EXPECT_NEAR(r.at_block.at(130)[0], 61.5, 1e-9);  // [ZERO] keeps the handwheel offset
  EXPECT_NEAR(r.at_block.at(140)[0], 70.0, 1e-9);  // [MANUAL] leaves it out
  EXPECT_NEAR(r.at_block.at(150)[0], 81.5, 1e-9);
  EXPECT_NEAR(channel(r)["offsets"]["manual"]["X"].get<double>(), 1.5, 1e-9);
}

TEST(CoordinateSystemsRun, HandwheelOffsetLeavesAlongThePathWithoutAJump) {
  const auto plc = temp_dir("hw_jump_plc") / "s.plc";
  std::ofstream(plc) << "0.5 handwheel X 1.5\n";
  ProgramRun r = run_blocks("hw_jump", "N10 G0 X0 Y0 Z0\nN20 G201 X1\nN30 G4 X2\nN40 G202\nN50 G0 X10\n"
                                "N60 #SUPPRESS OFFSETS G1 X20 F600\nN70 M30\n",
                     "--plc " + plc.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  double n60_start_s = 0;
  for (const json& e : r.events)
    if (e["ev"] == "block" && e["n"] == 60) n60_start_s = e["t"].get<double>();
  const auto rows = split(read_file(r.dir / "t.csv"), '\n');
  double last = 11.5, biggest_step = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto cols = split(rows[i], ',');
    if (std::stod(cols[0]) < n60_start_s) continue;
    const double x = std::stod(cols[1]);
    biggest_step = std::max(biggest_step, std::abs(x - last));
    last = x;
  }
  EXPECT_NEAR(last, 20.0, 1e-9);
  // F600 = 0.01 mm of the 10 mm path per 1 ms cycle; the 1.5 mm go out in
  // step with it (0.0015 per cycle): 0.0085 mm per cycle, never 1.5 at once.
  EXPECT_LT(biggest_step, 0.0101);
}

// Item 18: the kernel variables of the offsets read the state in force at
// the reading block. Each value is read into a P parameter, then X moves to
// it with no offset on X (G53, D0): machine X = the value.
std::string show_in_x(int first_n, int count) {
  std::string blocks = "N" + std::to_string(first_n - 10) + " #ROTATION OFF\nN" + std::to_string(first_n - 5) +
                       " G53 D0\n";
  for (int i = 1; i <= count; ++i)
    blocks += "N" + std::to_string(first_n + 10 * (i - 1)) + " G0 X[P" + std::to_string(i) + "]\n";
  return blocks + "N" + std::to_string(first_n + 10 * count) + " M30\n";
}

TEST(CoordinateSystemsRun, ToolRotationZeroAndPositionVariablesReadTheStateInForce) {
  ProgramRun r = run_blocks("kvars",
                     "N10 G54 D1 G0 X1 Y2 Z3\n"
                     "N20 P1 = V.A.ABS.X P2 = V.A.ABS.Z P3 = V.G.NP_AKT.V.Y\n"
                     "N30 #ROTATION ON [ANGLE=30 CENTER1=10 CENTER2=5]\n"
                     "N40 P4 = V.G.WZ_AKT.NR P5 = V.G.WZ_AKT.L P6 = V.G.WZ_AKT.R\n"
                     "N50 P7 = V.G.ROT_ACTIVE P8 = V.G.ROT_ANGLE P9 = V.G.ROT_CENTER1 P10 = V.G.ROT_CENTER2\n" +
                         show_in_x(200, 10));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const double want[] = {1, 3, 50,        // ABS X, ABS Z (program coordinates), G54 Y
                         1, 100, 5,       // D1: number, length, radius (tools.lis)
                         1, 30, 10, 5};  // #ROTATION ON [ANGLE=30 CENTER1=10 CENTER2=5]
  for (int i = 0; i < 10; ++i) EXPECT_NEAR(r.at_block.at(210 + 10 * i)[0], want[i], 1e-9) << "P" << i + 1;
}

TEST(CoordinateSystemsRun, VariablesAfterTheirFunctionIsOffReadZero) {
  ProgramRun r = run_blocks("kvars_off", "N10 G54 D1 G0 X0 Y0 Z0\nN20 #ROTATION ON [ANGLE=30]\nN30 #ROTATION OFF\nN35 D0 G53\n"
                                  "N40 P1 = V.G.ROT_ACTIVE + V.G.ROT_ANGLE + V.G.WZ_AKT.L + V.G.NP_AKT.V.X + 7\n" +
                                      show_in_x(200, 1));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(r.at_block.at(210)[0], 7.0, 1e-9);
}

// V.A.MEIN: the measuring offset G101 included (measure.nc: 7 mm on Z).
TEST(CoordinateSystemsRun, MeinReadsTheMeasuringOffsetIncluded) {
  ProgramRun r = run_blocks("kvars_mein", "N10 G17 G90 G54 D1 G0 X0 Y0 Z-50\nN20 G100 Z-80 F300\nN30 G101 Z1\n"
                                   "N40 P1 = V.A.MEIN.Z\nN50 G102\nN60 P2 = V.A.MEIN.Z + 1\n" + show_in_x(200, 2));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(r.at_block.at(210)[0], 7.0, 1e-9);  // -73 measured - -80 target
  EXPECT_NEAR(r.at_block.at(220)[0], 1.0, 1e-9);  // G102 removed it
}

// Item 20: the offset events and --final show the whole CS stack; the
// outermost CS keeps the plain keys, the next ones are prefixed "2." ...
TEST(CoordinateSystemsRun, NestedCsAreAllReported) {
  ProgramRun r = run_blocks("cs_nested", "N10 G54 G0 X0 Y0 Z0\nN20 #CS ON [1][10,0,0,0,0,0]\n"
                                  "N30 #CS ON [2][0,5,0,0,0,90]\nN40 G0 X1 Y0\nN50 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // CS 2 turned 90 deg: X1 -> (0,1) +(0,5) -> CS 1 +(10,0) -> G54 (100,50)
  EXPECT_NEAR(r.at_block.at(50)[0], 110.0, 1e-9);
  EXPECT_NEAR(r.at_block.at(50)[1], 56.0, 1e-9);
  const json* ev = nullptr;
  for (const json& e : r.events)
    if (e["ev"] == "offset" && e["kind"] == "cs" && e["line"] == 5) ev = &e;
  ASSERT_NE(ev, nullptr);
  for (const json* v : {&(*ev)["values"], &channel(r)["offsets"]["cs"]}) {
    EXPECT_EQ(v->at("X"), 10.0);
    EXPECT_EQ(v->at("2.X"), 0.0);
    EXPECT_EQ(v->at("2.Y"), 5.0);
    EXPECT_EQ(v->at("2.angle3"), 90.0);
  }
}

TEST(CoordinateSystemsRun, CsSelectReportsTheStackAndHowManyAct) {
  ProgramRun r = run_blocks("cs_select", "N10 G54 G0 X0 Y0 Z0\nN20 #CS ADD [A][10,0,0,0,0,0]\n"
                                  "N30 #CS ADD [B][0,5,0,0,0,0]\nN40 #CS SELECT [A]\nN50 G0 X0 Y0\nN60 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NEAR(r.at_block.at(60)[0], 110.0, 1e-9);  // only A acts: 100 + 10
  EXPECT_NEAR(r.at_block.at(60)[1], 50.0, 1e-9);
  const json& cs = channel(r)["offsets"]["cs"];
  EXPECT_EQ(cs.at("X"), 10.0);
  EXPECT_EQ(cs.at("2.Y"), 5.0);
  EXPECT_EQ(cs.at("selected"), 1.0);
}

TEST(CoordinateSystemsRun, CsOffBringingAZeroOffsetBackIsAnEvent) {
  ProgramRun r = run_blocks("cs_off_zero", "N10 G54 G0 X0 Y0 Z0\nN20 #CS ON [0,0,0,0,0,0]\nN30 G55\nN40 #CS OFF\n"
                                    "N50 M30\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  bool zero_back = false;
  for (const json& e : r.events)
    if (e["ev"] == "offset" && e["kind"] == "zero" && e["line"] == 6) zero_back = e["values"]["X"] == 100.0;
  EXPECT_TRUE(zero_back);
}

}  // namespace
}  // namespace nck::app
