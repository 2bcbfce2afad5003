// Spindle-path functions end to end through `nck run` (FCT-S1 2.8.6, 2.8.7,
// 2.8.9; docs/nc-language.md): the trace's numbers against values by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "spindle_path_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

double n_css(double v_m_min, double r_mm) { return 1000.0 * v_m_min / (2.0 * std::numbers::pi * r_mm); }

TEST(SpindlePath, FacingWithG96FollowsTheRadiusUpToG196AndG97FreezesIt) {
  const PathRun r = run_example_program("lathe", "facing.nc", "css");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const double t70 = r.block_t(70), t80 = r.block_t(80), t100 = r.block_t(100), t110 = r.block_t(110);
  ASSERT_GT(t70, 0);
  std::size_t checked = 0, limited = 0;
  for (std::size_t k = r.index(t70) + 10; k < r.index(t80); ++k) {
    const double x = r.rows[k].at("X"), rpm = r.rows[k].at("S1.rpm");
    // n = 1000 x 150 / (2 pi X), at most G196 S2000: X40 596.8, X20 1193.7 rpm.
    const double want = std::min(n_css(150, x), 2000.0);
    EXPECT_NEAR(rpm, want, 0.005 * want + 0.5) << "X" << x;
    if (want == 2000.0) ++limited;
    ++checked;
  }
  EXPECT_GT(checked, 10000u);
  EXPECT_GT(limited, 4000u);  // from X11.94 to the centre
  EXPECT_NEAR(n_css(150, 20), 1193.66, 0.01);
  // G97 keeps the speed reached (2000 rpm) until M5.
  EXPECT_DOUBLE_EQ(r.at(t100 + kDt, "S1.rpm"), 2000.0);
  EXPECT_DOUBLE_EQ(r.at(t110 - kDt, "S1.rpm"), 2000.0);
  EXPECT_TRUE(r.of("warning").empty());
}

// The radius is the tool tip's: D1 shifts the machine X by 25 mm (tools.lis).
TEST(SpindlePath, G96RadiusLeavesTheToolOffsetOut) {
  const PathRun r = run_text("lathe", "G18 G90\nG196 S2500\nT1 D1 M3 S1000\nG0 X20 Z-50\nG96 S150\nG4 0.5\nM30\n",
                             "css_tool");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const double t = r.line_t(7) - kDt;
  EXPECT_NEAR(r.at(t, "X"), 45.0, 1e-9);           // machine X = 20 + 25
  EXPECT_NEAR(r.at(t, "S1.rpm"), n_css(150, 20), 0.01);  // 1193.66 rpm, not 530.5 (r = 45)
}

TEST(SpindlePath, G96StartSpeedLimitedWarns20633) {
  const PathRun r = run_text("lathe", "G18 G90\nG196 S500\nM3 S300\nG0 X10 Z2\nG96 S150\nG1 X5 F100\nM30\n", "css_warn");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const auto w = r.of("warning");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0]["id"], 20633);
  EXPECT_EQ(w[0]["line"], 5);
  // At X10: 2387 rpm wanted, G196 gives 500.
  EXPECT_DOUBLE_EQ(r.rows.back().at("S1.rpm"), 500.0);
}

TEST(SpindlePath, ProfileWithG95FeedsSpeedTimesFeedPerRevolution) {
  const PathRun r = run_example_program("lathe", "profile.nc", "g95");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  // N50 G1 Z-20 at 800 rpm x 0.2 mm = 160 mm/min = 2.6667 mm/s.
  const std::size_t a = r.index(r.block_t(50)) + 100, b = r.index(r.block_t(60)) - 100;
  const double v = (r.rows[a].at("Z") - r.rows[b].at("Z")) / (static_cast<double>(b - a) * kDt);
  EXPECT_NEAR(v, 800 * 0.2 / 60, 1e-4);
  // The arc and the next line at the same path speed: N70 Z-30..-45 takes 15 / 2.6667 = 5.625 s.
  EXPECT_NEAR(r.block_t(80) - r.block_t(70), 5.625, 0.01);
}

// Decision (docs/decisions.md, "Spindle-path couplings"): under G95 the path follows the spindle's
// set-point speed of each cycle, also while the spindle still ramps.
TEST(SpindlePath, G95FollowsTheRampingSpindleEachCycle) {
  const PathRun r = run_text("lathe", "G18 G90\nM3 S400\nG0 X10 Z2\nG95 F0.2 S800 G1 Z-20\nM30\n", "g95ramp");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  std::size_t ramping = 0;
  for (std::size_t k = 1; k + 1 < r.rows.size(); ++k) {
    const double rpm_before = r.rows[k - 1].at("S1.rpm");
    const double dz = r.rows[k - 1].at("Z") - r.rows[k].at("Z");
    if (!(dz > 0) || r.rows[k].at("Z") < -19.9 || r.rows[k].at("Z") > 1.99) continue;
    if (rpm_before > 401 && rpm_before < 799) ++ramping;
    // ΔZ of cycle k = rpm of cycle k-1 x 0.2 / 60 x dt (trace rounding 1e-6 mm).
    EXPECT_NEAR(dz, rpm_before * 0.2 / 60 * kDt, 2e-6) << "row " << k;
  }
  EXPECT_GT(ramping, 100u);  // the spindle ramped 400 -> 800 rpm while the path ran
}

// TF5200 G95: with a PLC main spindle (plc_control) G95 uses the programmed
// speed only: 500 rpm x 0.1 mm = 0.8333 mm/s while the spindle still ramps.
TEST(SpindlePath, G95WithAPlcMainSpindleUsesTheProgrammedSpeed) {
  const auto m = patched_example("mill", "g95plc_machine", "channel1.lis",
                                 "spdl_anzahl 3\nspindel[2].bezeichnung S3\nspindel[2].log_achs_nr 9\n"
                                 "spindel[2].plc_control 1\nmain_spindle_ax_nr 9\n");
  const PathRun r = run_text(m.dir.string(), "G90 X0 Y0 Z0\nM3 S500\nG95 F0.1 G1 X10\nM30\n", "g95plc");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const std::size_t a = r.index(r.line_t(3)) + 100;
  EXPECT_LT(r.rows[a + 500].at("S3.rpm"), 400.0);  // ramping
  EXPECT_NEAR(r.rows[a].at("X") - r.rows[a + 1000].at("X"), -500 * 0.1 / 60, 1e-6);
}

TEST(SpindlePath, G95WithStoppedSpindleIs60131) {
  const PathRun r = run_text("lathe", "G18 G90\nG0 X10 Z2\nG95 F0.2 G1 Z-20\nM30\n", "g95stop");
  EXPECT_NE(r.cli.exit_code, 0);
  const auto e = r.of("error");
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0]["id"], 60131);
  EXPECT_EQ(e[0]["line"], 3);
  EXPECT_EQ(r.of("end").back()["reason"], "error");
}

TEST(SpindlePath, G93TakesFAsTheBlockTime) {
  const PathRun r = run_text("lathe", "G18 G90\nG0 X10 Z2\nG93 G1 Z-18 F2\nG94 G1 Z-20 F600\nM30\n", "g93");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  // 20 mm in 2 s (10 mm/s, the ramps at 3000 mm/s^2 add a few ms).
  EXPECT_NEAR(r.line_t(4) - r.line_t(3), 2.0, 0.01);
}

// G194 F25: a quarter of Z's max_speed_mm_s (500 mm/s) = 125 mm/s; F100 is refused.
TEST(SpindlePath, G194WeightsTheAxisMaximum) {
  const PathRun r = run_text("lathe", "G18 G90\nG0 X10 Z2\nG194 G1 Z-398 F25\nM30\n", "g194");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const std::size_t k = r.index(r.line_t(3)) + 1000;
  EXPECT_NEAR(r.rows[k].at("Z") - r.rows[k + 1000].at("Z"), 125.0, 1e-6);
  const PathRun bad = run_text("lathe", "G18 G90\nG194 G1 Z-20 F100\nM30\n", "g194bad");
  EXPECT_NE(bad.cli.exit_code, 0);
  ASSERT_EQ(bad.of("error").size(), 1u);
  EXPECT_EQ(bad.of("error")[0]["id"], 920090);
}

// Three G33 passes start on the zero mark (the spindle passes 0 deg in the
// cycle before Z moves) and cut the same groove: at Z-10 the spindle stands
// at the same angle in each pass.
TEST(SpindlePath, ThreadInThreeG33PassesStartsOnTheZeroMark) {
  const PathRun r = run_example_program("lathe", "thread.nc", "g33");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const double step_deg = 400 * 6 * kDt;  // 2.4 deg per cycle at 400 rpm
  std::vector<double> at_z10;
  for (long n : {50L, 90L, 130L}) {
    std::size_t k = r.index(r.block_t(n));
    while (r.rows[k + 1].at("Z") >= 5.0 - 1e-9) ++k;  // row k: last before Z moves
    EXPECT_GE(r.rows[k].at("S1.pos"), 0.0) << "N" << n;
    EXPECT_LT(r.rows[k].at("S1.pos"), step_deg + 1e-6) << "N" << n;
    // Feed = 400 rpm x 2 mm = 800 mm/min along Z in the middle of the pass.
    std::size_t m = k + 1000;
    EXPECT_NEAR((r.rows[m].at("Z") - r.rows[m + 1000].at("Z")) / 1.0, 800.0 / 60.0, 1e-4);
    while (r.rows[k].at("Z") > -10) ++k;
    at_z10.push_back(r.rows[k].at("S1.pos"));
  }
  EXPECT_NEAR(wrapped_step(at_z10[0], at_z10[1]), 0.0, step_deg);
  EXPECT_NEAR(wrapped_step(at_z10[0], at_z10[2]), 0.0, step_deg);
  // Each pass's wait for the mark is a wait like the others (issue 48 item
  // 5): a wait event at the pass's start, its end in the cycle Z moves.
  std::vector<nlohmann::json> waits, ends;
  for (const nlohmann::json& e : r.of("wait")) if (e["reason"] == "zero_mark") waits.push_back(e);
  for (const nlohmann::json& e : r.of("wait_end")) if (e["reason"] == "zero_mark") ends.push_back(e);
  ASSERT_EQ(waits.size(), 3u);
  ASSERT_EQ(ends.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(waits[i]["spindle"], "S1");
    EXPECT_EQ(waits[i]["line"], ends[i]["line"]);
    EXPECT_GT(ends[i]["t"].get<double>(), waits[i]["t"].get<double>());
    EXPECT_LT(ends[i]["t"].get<double>() - waits[i]["t"].get<double>(), 60.0 / 400 + kDt);  // within a turn
  }
}

// P-CHAN-00836: with thread_cutting.ignore_override 1 a feed override of
// 50 % leaves the thread at 400 rpm x 2 mm; with 0 (default) it acts.
TEST(SpindlePath, G33FeedOverrideFollowsIgnoreOverride) {
  const auto plc = temp_dir("g33ovr_plc") / "ovr.plc";
  std::ofstream(plc) << "0.0 feed_override 50\n";
  const std::string prog = "G18 G90\nM3 S400\nG0 X36 Z5\nG33 Z-30 K2\nM30\n";
  const std::string ignoring =
      patched_example("lathe", "g33ovr_machine", "channel1.lis", "thread_cutting.ignore_override 1").dir.string();
  for (const auto& [machine, want] : {std::pair<std::string, double>{"lathe", 0.5 * 800 / 60.0},
                                      std::pair<std::string, double>{ignoring, 800 / 60.0}}) {
    const PathRun r = run_text(machine, prog, "g33ovr", "--plc " + plc.string());
    ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
    const std::size_t k = before_move(r, r.index(r.line_t(4)), "Z");
    EXPECT_NEAR(r.rows[k + 500].at("Z") - r.rows[k + 1500].at("Z"), want, 1e-4) << machine;
  }
}

// P-CHAN-00837: with thread_cutting.thread_chain 1 consecutive G33 blocks
// run as one thread. Into the collinear second block the path passes at
// 400 rpm x 2 mm = 13.33 mm/s; into the tapered third block (an 8.5 deg
// kink) it slows to the corner limit but does not stop, and neither block
// waits for the zero mark again. A feed override of 50 % does not act in
// the chain. Without the parameter every G33 block starts from standstill.
TEST(SpindlePath, ThreadChainRunsConsecutiveG33BlocksWithoutStop) {
  const auto plc = temp_dir("tchain_plc") / "ovr.plc";
  std::ofstream(plc) << "0.0 feed_override 50\n";
  const std::string prog = "G18 G90\nM3 S400\nG0 X36 Z5\nG33 Z-10 K2\nG33 Z-20\nG33 Z-30 X37.5\nG0 X40\nM30\n";
  const std::string chain =
      patched_example("lathe", "tchain_machine", "channel1.lis", "thread_cutting.thread_chain 1").dir.string();
  auto speed = [](const PathRun& r, std::size_t k) {
    return std::hypot(r.rows[k].at("Z") - r.rows[k - 1].at("Z"), r.rows[k].at("X") - r.rows[k - 1].at("X")) / kDt;
  };
  auto slowest = [&](const PathRun& r, std::size_t k) {
    double v = 1e9;
    for (std::size_t i = k - 20; i < k + 20; ++i) v = std::min(v, speed(r, i));
    return v;
  };
  const double thread_mm_s = 400 * 2 / 60.0, resolution = 2e-3;  // trace: 1e-6 mm per 1 ms
  const PathRun r = run_text(chain, prog, "tchain", "--plc " + plc.string());
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const std::size_t second = r.index(r.line_t(5)), third = r.index(r.line_t(6));
  EXPECT_NEAR(slowest(r, second), thread_mm_s, resolution);
  EXPECT_GT(slowest(r, third), 1.0);
  EXPECT_LT(slowest(r, third), thread_mm_s - 1.0);
  // Back on the thread (override ignored): Z at 400 rpm x 2 mm.
  EXPECT_NEAR(r.rows[third + 499].at("Z") - r.rows[third + 500].at("Z"), thread_mm_s * kDt, 1e-6);
  // The plain lathe: the second block waits at standstill for the zero
  // mark, and the override acts.
  const PathRun plain = run_text("lathe", prog, "tchain_plain", "--plc " + plc.string());
  ASSERT_EQ(plain.cli.exit_code, 0) << plain.cli.output;
  EXPECT_EQ(slowest(plain, plain.index(plain.line_t(5))), 0.0);
  EXPECT_NEAR(speed(plain, plain.index(plain.line_t(5)) + 500), 0.5 * thread_mm_s, resolution);
}

TEST(SpindlePath, RigidTappingG331G332TurnsWithThePitchAndBack) {
  const PathRun r = run_example_program("lathe", "tapping.nc", "g331");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const std::size_t a = before_move(r, r.index(r.block_t(30)), "Z");
  const std::size_t b = r.index(r.block_t(40)), c = r.index(r.block_t(50));
  // The spindle was positioned to 0 deg before tapping.
  EXPECT_NEAR(r.rows[a].at("S1.pos"), 0.0, 1e-3);
  auto [turn, travel] = turn_and_travel(r, a, b - 1, "Z");
  EXPECT_NEAR(travel, -25.0, 1e-6);
  EXPECT_NEAR(turn, 20 * 360.0, 1e-3);          // 25 mm / 1.25 mm = 20 turns, M3 sense (K > 0)
  EXPECT_NEAR(turn / -travel, 360 / 1.25, 1e-6);  // 288 deg per mm
  auto [back, up] = turn_and_travel(r, b - 1, c - 1, "Z");
  EXPECT_NEAR(up, 25.0, 1e-6);
  EXPECT_NEAR(back, -20 * 360.0, 1e-3);  // G332 turns back
  // 500 rpm x 1.25 = 625 mm/min in the middle of the tap.
  EXPECT_NEAR((r.rows[a + 500].at("Z") - r.rows[a + 1500].at("Z")), 625.0 / 60.0, 1e-4);
  EXPECT_NEAR(r.rows[a + 1000].at("S1.rpm"), 500.0, 1e-3);
}

TEST(SpindlePath, M3InAG331BlockIsAnError) {
  const PathRun r = run_text("lathe", "G18 G90\nG0 X0 Z5\nG331 Z-20 K1.25 S500 M3\nM30\n", "g331m3");
  EXPECT_NE(r.cli.exit_code, 0);
  ASSERT_FALSE(r.of("error").empty());
  EXPECT_EQ(r.of("error")[0]["id"], 920069);
  EXPECT_EQ(r.of("error")[0]["line"], 3);
}

// FCT-S1 2.8.6, second example as written: F300 S200 = pitch 1.5 mm, the
// spindle positioned to 180 deg, negative S to retract.
TEST(SpindlePath, G63SeedExampleTracksTheSpindleWithThePath) {
  const PathRun r = run_example_program("mill", "tapping.nc", "g63");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const std::size_t a = r.index(r.block_t(30)) - 1, b = r.index(r.block_t(40)), c = r.index(r.block_t(50));
  EXPECT_NEAR(r.rows[a].at("S1.pos"), 180.0, 1e-3);  // M19 S.POS180
  auto [turn, travel] = turn_and_travel(r, a, b - 1, "Z");
  EXPECT_NEAR(travel, -50.0, 1e-6);
  EXPECT_NEAR(turn, 50 / 1.5 * 360.0, 1e-3);  // 33.3 turns forward
  EXPECT_NEAR((r.rows[a + 1000].at("Z") - r.rows[a + 2000].at("Z")), 300.0 / 60.0, 1e-4);  // F300
  EXPECT_NEAR(r.rows[a + 1000].at("S1.rpm"), 200.0, 1e-3);
  auto [back, up] = turn_and_travel(r, b - 1, c - 1, "Z");
  EXPECT_NEAR(up, 100.0, 1e-6);
  EXPECT_NEAR(back, -100 / 1.5 * 360.0, 1e-3);  // S-200: the spindle turns back
  EXPECT_NEAR(r.rows[c - 1].at("S1.pos"), std::fmod(180.0 + 120.0 - 240.0 + 720.0, 360.0), 1e-3);
  // G01 ends G63: the spindle leaves axis mode (event mode "stop" at N50).
  bool stopped = false;
  for (const json& e : r.of("spindle"))
    if (e["t"].get<double>() == r.block_t(50) && e["mode"] == "stop") stopped = true;
  EXPECT_TRUE(stopped);
}

// FCT-S1 2.8.6, first example: F250 S200 = pitch 1.25 mm; G4 keeps G63.
TEST(SpindlePath, G63FirstSeedExampleAndDwellKeepsTapping) {
  const PathRun r = run_text("mill",
                         "G01 F2000 G90 X0 Y0 Z0\nM19 S.POS=0 M3 S100\nG63 Z-50 F250 S200\nG4 X0.1\n"
                         "Z0 S-200\nG01 F1000 X100\nM30\n",
                         "g63a");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const std::size_t a = r.index(r.line_t(3)) - 1, b = r.index(r.line_t(4));
  auto [turn, travel] = turn_and_travel(r, a, b - 1, "Z");
  EXPECT_NEAR(turn / -travel, 360 / 1.25, 1e-6);  // F = 200 x 1.25 = 250 mm/min
  EXPECT_NEAR((r.rows[a + 1000].at("Z") - r.rows[a + 2000].at("Z")), 250.0 / 60.0, 1e-4);
  // The spindle stays an axis through G4: only one axis-mode entry.
  int axis_events = 0;
  for (const json& e : r.of("spindle"))
    if (e["mode"] == "axis") ++axis_events;
  EXPECT_EQ(axis_events, 1);
}

TEST(SpindlePath, G63NeedsTheSpindleAtStandstill) {
  const PathRun r = run_text("mill", "G90 X0 Y0 Z0\nM3 S100\nG63 Z-50 F250 S200\nM30\n", "g63run");
  EXPECT_NE(r.cli.exit_code, 0);
  ASSERT_EQ(r.of("error").size(), 1u);
  EXPECT_EQ(r.of("error")[0]["id"], 950008);
  EXPECT_EQ(r.of("error")[0]["line"], 3);
}

TEST(SpindlePath, G63WithG95Is20635) {
  const PathRun r = run_text("mill", "G90 X0 Y0 Z0\nM19 S.POS=0 S100\nG95 F1\nG63 Z-50 F250 S200\nM30\n", "g63g95");
  EXPECT_NE(r.cli.exit_code, 0);
  ASSERT_EQ(r.of("error").size(), 1u);
  EXPECT_EQ(r.of("error")[0]["id"], 20635);
}

// Bad input ends the channel with the ID and the line (TF5200 G63, G331, G33).
TEST(SpindlePath, IllegalCouplingsEndTheChannelWithTheirId) {
  struct Case {
    const char* machine;
    const char* program;
    int id;
    int line;
  };
  const Case cases[] = {
      {"mill", "G90 X0 Y0 Z0\nM19 S.POS=0 S100\nG63 Z-50 F0 S200\nM30\n", 930002, 3},    // G63 with F0
      {"mill", "G90 X0 Y0 Z0\nM19 S.POS=0 S100\nG63 Z-50 F250 S0\nM30\n", 20007, 3},    // G63 with S0
      {"lathe", "G18 G90\nM3 S400\nG96 S100\nG63 Z-5 F250 S200\nM30\n", 20636, 4},      // G63 under G96
      {"lathe", "G18 G90\nM3 S400\nG0 X36 Z5\nG33 Z-30 K0\nM30\n", 920013, 4},        // pitch 0
      {"lathe", "G18 G90\nG196 S0\nM30\n", 120169, 2},                                 // G196 max 0
  };
  int i = 0;
  for (const Case& c : cases) {
    const PathRun r = run_text(c.machine, c.program, "bad" + std::to_string(i++));
    EXPECT_NE(r.cli.exit_code, 0) << c.program;
    ASSERT_EQ(r.of("error").size(), 1u) << c.program;
    EXPECT_EQ(r.of("error")[0]["id"], c.id) << c.program;
    EXPECT_EQ(r.of("error")[0]["line"], c.line) << c.program;
    EXPECT_EQ(r.of("end").back()["reason"], "error") << c.program;
  }
}

// A negative K taps a left-hand thread: the spindle turns M4 sense going in.
TEST(SpindlePath, G331NegativePitchTurnsTheOtherWay) {
  const PathRun r = run_text("lathe", "G18 G90\nG0 X0 Z5\nG331 Z-5 K-1 S300\nG332 Z5\nG0 Z10\nM30\n", "g331lh");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const std::size_t a = before_move(r, r.index(r.line_t(3)), "Z"), b = r.index(r.line_t(4));
  auto [turn, travel] = turn_and_travel(r, a, b - 1, "Z");
  EXPECT_NEAR(travel, -10.0, 1e-6);
  EXPECT_NEAR(turn, -10 * 360.0, 1e-3);
}

TEST(SpindlePath, G33PitchAxisThatDoesNotMoveIs120175) {
  const PathRun r = run_text("lathe", "G18 G90\nM3 S400\nG0 X36 Z5\nG33 X30 K2\nM30\n", "g33axis");
  EXPECT_NE(r.cli.exit_code, 0);
  ASSERT_EQ(r.of("error").size(), 1u);
  EXPECT_EQ(r.of("error")[0]["id"], 120175);
  EXPECT_EQ(r.of("error")[0]["line"], 4);
}

}  // namespace
}  // namespace nck::app
