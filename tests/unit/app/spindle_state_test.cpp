// What an S word alone does depends on what the spindle really does when the
// block executes, whoever commanded it (acceptance review, issue 9): the
// program, the PLC, another channel. FCT-S1 2.3.1: endless rotation ends with
// M5, G74 or M19; after that an S word only stores the speed.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

// The `spindle` events of one spindle from a run of `programs` (channel 1,
// 2...) on `machine`, with an optional PLC scenario.
struct SpindleRun {
  int exit_code = -1;
  std::string output;
  std::vector<json> events;  // every event of the run
};

SpindleRun run_programs(const std::filesystem::path& machine, const std::vector<std::string>& programs,
                        const std::string& plc = "") {
  const auto dir = temp_dir("spdl_state");
  std::string args = "run " + machine.string();
  for (std::size_t i = 0; i < programs.size(); ++i) {
    const auto p = dir / ("ch" + std::to_string(i + 1) + ".nc");
    std::ofstream(p) << programs[i];
    args += " " + p.string();
  }
  if (!plc.empty()) {
    std::ofstream(dir / "s.plc") << plc;
    args += " --plc " + (dir / "s.plc").string();
  }
  CliResult c = run_nck(args + " --events " + (dir / "e.jsonl").string());
  return {c.exit_code, c.output, read_jsonl(dir / "e.jsonl")};
}

std::filesystem::path example(const std::string& name) { return root() + "/examples/" + name; }

// Commanded speeds of `spindle` in order (rpm of its `spindle` events in rotation).
std::vector<double> rotations(const SpindleRun& r, const std::string& spindle) {
  std::vector<double> out;
  for (const json& e : r.events)
    if (e["ev"] == "spindle" && e["spindle"] == spindle && e["mode"] == "rotate")
      out.push_back(e["rpm"].get<double>());
  return out;
}

bool turned_at(const SpindleRun& r, const std::string& spindle, double rpm) {
  for (double v : rotations(r, spindle))
    if (v == rpm) return true;
  return false;
}

// "Endless rotation is terminated by ... homing (G74)": the later S2000 only stores.
TEST(SpindleState, SAfterG74OnlyStoresTheSpeed) {
  SpindleRun r = run_programs(example("mill"), {"M3 S1000\nG4 X0.5\nG74 S1\nG4 X2\nS2000\nG4 X0.5\nM30\n"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(turned_at(r, "S1", 1000));
  EXPECT_FALSE(turned_at(r, "S1", 2000));
}

// A PLC spindle reset stops the spindle; the program's next S must not restart it.
TEST(SpindleState, SAfterPlcSpindleResetOnlyStoresTheSpeed) {
  SpindleRun r = run_programs(example("mill"), {"M3 S1000\nG4 X2\nS2000\nG4 X0.5\nM30\n"},
                              "1.0 spindle_reset S1\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(turned_at(r, "S1", 1000));
  EXPECT_FALSE(turned_at(r, "S1", 2000));
}

// Spindle stop (M5) from the PLC ends the rotation just as the program's M5 does.
TEST(SpindleState, SAfterPlcM5OnlyStoresTheSpeed) {
  SpindleRun r = run_programs(example("mill"), {"M3 S1000\nG4 X2\nS2000\nG4 X0.5\nM30\n"},
                              "1.0 spindle_cmd S1 M5\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(turned_at(r, "S1", 1000));
  EXPECT_FALSE(turned_at(r, "S1", 2000));
}

// Channel 1 starts S2 (the main spindle of both channels, FCT-S1 2.2.5.2);
// channel 2's S2000 changes the speed of that rotation.
TEST(SpindleState, SChangesASpeedAnotherChannelStarted) {
  SpindleRun r = run_programs(example("two-channel"), {"M3 S1000\nG4 X3\nM30\n", "G4 X1\nS2000\nG4 X1\nM30\n"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(rotations(r, "S2"), (std::vector<double>{1000, 2000}));
}

// The PLC starts S1 with an external command; the program's S800 changes its speed.
TEST(SpindleState, SChangesASpeedThePlcStarted) {
  SpindleRun r = run_programs(example("mill"), {"G4 X1\nS800\nG4 X1\nM30\n"}, "0.0 spindle_cmd S1 M3 REV500\n");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(rotations(r, "S1"), (std::vector<double>{500, 800}));
}

// TF5200 #MAIN SPINDLE [<spindle_name> | <log_axis_nr>]. In the mill S2
// has log_achs_nr 5: it becomes S, the former main spindle S1 stays still.
TEST(SpindleState, MainSpindleByLogicalAxisNumber) {
  SpindleRun r = run_programs(example("mill"), {"#MAIN SPINDLE [5]\nM3 S1000\nG4 X0.5\nM30\n"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(rotations(r, "S2"), (std::vector<double>{1000}));
  EXPECT_TRUE(rotations(r, "S1").empty());
}

TEST(SpindleState, MainSpindleWithAnUnknownLogicalAxisNumberIsReported) {
  SpindleRun r = run_programs(example("mill"), {"#MAIN SPINDLE [9]\nM3 S1000\nM30\n"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("error 920063"), std::string::npos) << r.output;
  EXPECT_TRUE(rotations(r, "S1").empty());
}

}  // namespace
}  // namespace nck::app
