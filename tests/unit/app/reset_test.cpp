// A channel reset through `nck run --plc` (issue 44, item 1; issue 45,
// item 9): the path brakes along its path with the deceleration in force
// (mill X/Y a_brems 2,500 mm/s^2) instead of stopping within one cycle,
// couplings stop together, a reset is not an error, and a reset after an
// error leaves the error state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "spindle_path_helpers.hpp"

namespace nck::app::testing {
namespace {

// The largest |second difference| / dt^2 of column `col` over rows [from, to).
double max_acceleration(const PathRun& r, const std::string& col, std::size_t from, std::size_t to) {
  double worst = 0;
  for (std::size_t i = std::max<std::size_t>(from, 1); i + 1 < to && i + 1 < r.rows.size(); ++i) {
    const double a = (r.rows[i + 1].at(col) - 2 * r.rows[i].at(col) + r.rows[i - 1].at(col)) / (kDt * kDt);
    worst = std::max(worst, std::abs(a));
  }
  return worst;
}

struct PlcRun {
  PathRun run;
  nlohmann::json final_state;
};

PlcRun run_with_plc(const std::string& machine, const std::string& program, const std::string& plc,
                    const std::string& name) {
  const auto dir = temp_dir(name + "_plc");
  write(dir / "s.plc", plc);
  PlcRun r{run_text(machine, program, name, "--plc " + (dir / "s.plc").string() + " --final " + (dir / "f.json").string()),
           {}};
  r.final_state = nlohmann::json::parse(read_file(dir / "f.json"));
  return r;
}

const nlohmann::json* end_event(const PathRun& r) {
  for (const nlohmann::json& e : r.events)
    if (e["ev"] == "end") return &e;
  return nullptr;
}

TEST(Reset, BrakesAlongThePathWithinTheAxisDeceleration) {
  // 50 mm/s along X, reset at 1 s: braking at 2,500 mm/s^2 takes 20 ms and
  // 0.5 mm (v^2 / 2a); the old reset stopped within one cycle (50,000 mm/s^2).
  const PlcRun plc = run_with_plc("mill", "N10 G90 G1 X250 F3000\nN20 M30\n", "1.0 reset\n", "reset_brakes");
  const PathRun& r = plc.run;
  EXPECT_EQ(r.cli.exit_code, 0) << r.cli.output;  // a reset is not an error
  EXPECT_EQ(r.cli.output.find("940007"), std::string::npos) << r.cli.output;
  EXPECT_NE(r.cli.output.find("0 error(s)"), std::string::npos) << r.cli.output;
  const nlohmann::json* end = end_event(r);
  ASSERT_NE(end, nullptr);
  EXPECT_EQ((*end)["reason"], "reset");
  // The row at 1 s is the reset's cycle: the row before it still at 50 mm/s.
  const std::size_t before = r.index(1.0) - 1;
  ASSERT_LT(before + 2, r.rows.size());
  const double v_before = (r.rows[before].at("X") - r.rows[before - 1].at("X")) / kDt;
  EXPECT_NEAR(v_before, 50.0, 1e-6);
  // v^2 / 2a less half a cycle's travel (the staircase of 1 ms steps)
  const double stand_x = r.rows.back().at("X");
  EXPECT_NEAR(stand_x - r.rows[before].at("X"), 50.0 * 50.0 / (2 * 2500) - 50.0 * kDt / 2, 1e-6);
  // + 2 mm/s^2: the trace's printed digits
  EXPECT_LE(max_acceleration(r, "X", before - 5, r.rows.size()), 2500 + 2.0);
  // The end comes at standstill, about 20 ms after the reset.
  EXPECT_NEAR((*end)["t"].get<double>() - 1.0, 0.020, 0.003);
  EXPECT_EQ(plc.final_state["end"], "reset");
  EXPECT_TRUE(plc.final_state["errors"].empty()) << plc.final_state.dump();
  const std::vector<nlohmann::json> states = r.of("state");
  ASSERT_FALSE(states.empty());
  EXPECT_EQ(states.back()["to"], "idle");
  EXPECT_EQ(states.back()["reason"], "reset");
  EXPECT_EQ(states.back()["t"], (*end)["t"]);  // running until the path stands
}

TEST(Reset, StandingChannelEndsAtOnce) {
  const PlcRun plc = run_with_plc("mill", "N10 G4 X2\nN20 M30\n", "0.5 reset\n", "reset_dwell");
  const PathRun& r = plc.run;
  EXPECT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const nlohmann::json* end = end_event(r);
  ASSERT_NE(end, nullptr);
  EXPECT_EQ((*end)["reason"], "reset");
  EXPECT_NEAR((*end)["t"].get<double>(), 0.5, 0.0015);
}

TEST(Reset, RigidTapStopsWithItsSpindleOnThePitch) {
  // Reset in the middle of G331 (625 mm/min): Z brakes, the spindle follows
  // it at 288 deg per mm to the end, so the thread is never torn.
  const PlcRun plc = run_with_plc("lathe", "N10 G18 G90\nN20 G0 X0 Z5\nN30 G331 Z-20 K1.25 S500\nN40 M30\n",
                                 "2.0 reset\n", "reset_tap");
  const PathRun& r = plc.run;
  EXPECT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const std::size_t a = before_move(r, r.index(r.block_t(30)), "Z");
  const std::size_t last = r.rows.size() - 1;
  ASSERT_GT(last, r.index(2.0));
  const auto [turn, travel] = turn_and_travel(r, a, last, "Z");
  EXPECT_LT(travel, -5.0);
  EXPECT_NEAR(turn / -travel, 360 / 1.25, 1e-4);  // S1.pos printed to 1e-4 deg
  // Both stand at the end: the last rows do not move.
  EXPECT_DOUBLE_EQ(r.rows[last].at("Z"), r.rows[last - 1].at("Z"));
  EXPECT_NEAR(r.rows[last].at("S1.rpm"), 0.0, 1e-9);
}

TEST(Reset, ThreadFollowsItsSpindleDown) {
  // Reset during a G33 pass (400 rpm x 2 mm): the spindle brakes with its
  // ramp (4,000 deg/s^2) and its drive's lag, and the path keeps the pitch
  // to the spindle's actual speed (one cycle behind, as the coupling reads
  // it) until both stand; braking the path alone (in 3 ms) would tear the
  // thread.
  const PlcRun r = run_with_plc("lathe", "N10 G18 G90 M3 S400\nN20 G0 X20 Z5\nN30 G33 Z-60 K2\nN40 M30\n",
                                "3.0 reset\n", "reset_thread");
  EXPECT_EQ(r.run.cli.exit_code, 0) << r.run.cli.output;
  const std::vector<Row>& rows = r.run.rows;
  const std::size_t at_reset = r.run.index(3.0);
  ASSERT_GT(rows.size(), at_reset + 500);
  for (std::size_t i = at_reset; i < rows.size(); ++i) {
    const double v_mm_s = (rows[i - 1].at("Z") - rows[i].at("Z")) / kDt;
    // 1e-3 mm/s: the trace's printed digits
    ASSERT_NEAR(v_mm_s, rows[i - 1].at("S1.act_rpm") / 60 * 2, 2e-3) << rows[i].at("t");
  }
  EXPECT_NEAR(rows.back().at("S1.act_rpm"), 0.0, 1e-9);
}

TEST(Reset, AfterAnErrorTheChannelIsIdleAndMdiRuns) {
  // Line 2 is a circle without centre (an error at 0 s); the reset makes
  // the channel idle and the MDI block runs.
  const PlcRun plc = run_with_plc("mill", "N10 G90 G1 X5 F600\nN20 G2 X10 Y0\nN30 M30\n",
                                 "1.0 reset\n1.1 mdi G1 X20 F1200\n", "reset_error");
  const PathRun& r = plc.run;
  EXPECT_EQ(r.cli.exit_code, 1) << r.cli.output;  // the error stays an error of the run
  std::vector<std::string> states;
  for (const nlohmann::json& e : r.events)
    if (e["ev"] == "state") states.push_back(e["to"].get<std::string>() + "/" + e["reason"].get<std::string>());
  const std::vector<std::string> want = {"running/start", "error/error", "idle/reset", "running/mdi", "idle/mdi"};
  EXPECT_EQ(states, want) << r.cli.output;
  EXPECT_NEAR(r.rows.back().at("X"), 20.0, 1e-9);
}

// The largest step of column `col` from one trace row to the next (mm).
double max_step(const PathRun& r, const std::string& col) {
  double worst = 0;
  for (std::size_t i = 1; i < r.rows.size(); ++i)
    worst = std::max(worst, std::abs(r.rows[i].at(col) - r.rows[i - 1].at(col)));
  return worst;
}

std::vector<long> warning_ids(const PathRun& r) {
  std::vector<long> ids;
  for (const nlohmann::json& e : r.of("warning")) ids.push_back(e["id"].get<long>());
  return ids;
}

TEST(Reset, DropsTheMdiTypedBeforeItAndPlansTheNextFromWhereThePathStands) {
  // X moves at 50 mm/s when the reset comes at 0.5 s; Y40 was typed before
  // it (prepared from X100, where the first text would have ended), Z-1 in
  // the reset's cycle (the path still brakes), Y5 once the channel is idle.
  // Before, Y40 ran from X100: the path jumped 80 mm in one cycle.
  const PlcRun plc = run_with_plc("mill", "N10 G90 G0 X0 Y0 Z0\nN20 M30\n",
                                 "0.1 mdi G90 G1 X100 F3000\n0.1 mdi G1 Y40\n0.5 reset\n0.5 mdi G1 Z-1\n"
                                 "1.0 mdi G90 G1 Y5 F3000\n",
                                 "reset_mdi");
  const PathRun& r = plc.run;
  EXPECT_EQ(r.cli.exit_code, 0) << r.cli.output;
  for (const char* axis : {"X", "Y", "Z"}) EXPECT_LE(max_step(r, axis), 50.0 * kDt + 1e-6) << axis;
  const std::vector<long> warnings = warning_ids(r);
  EXPECT_NE(std::find(warnings.begin(), warnings.end(), 930712), warnings.end()) << r.cli.output;  // Y40 dropped
  EXPECT_NE(std::find(warnings.begin(), warnings.end(), 930710), warnings.end()) << r.cli.output;  // Z-1 refused
  const Row& last = r.rows.back();
  EXPECT_GT(last.at("X"), 18.0);  // 0.4 s at 50 mm/s, braked within 0.5 mm
  EXPECT_LT(last.at("X"), 21.0);
  EXPECT_NEAR(last.at("Y"), 5.0, 1e-9);
  EXPECT_NEAR(last.at("Z"), 0.0, 1e-9);
}

}  // namespace
}  // namespace nck::app::testing
