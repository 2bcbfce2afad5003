// nck run and homing (P-AXIS-00277, docs/cli.md "nck run --unhomed"): the
// dry run assumes a homed machine, so tests/data/machine_homing (X and Z
// require homing) runs move.nc as any machine; with --unhomed the block
// that moves X is refused (930740 naming X, at its line) and nothing moved;
// G74 first homes, then the program runs; --final lists `homed` per axis.
#include <gtest/gtest.h>

#include <string>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

const std::string kMachine = root() + "/tests/data/machine_homing";

struct Ran {
  CliResult cli;
  std::vector<nlohmann::json> events;
  nlohmann::json final_state;
};

Ran run_homing(const std::string& program, const std::string& extra, const std::string& name) {
  const auto d = temp_dir("homing_" + name);
  Ran r;
  r.cli = run_nck("run " + kMachine + " " + kMachine + "/" + program + " --events " + (d / "e.jsonl").string() +
                  " --final " + (d / "f.json").string() + " --no-progress " + extra);
  r.events = read_jsonl(d / "e.jsonl");
  std::ifstream f(d / "f.json");
  r.final_state = nlohmann::json::parse(f, nullptr, false);
  std::filesystem::remove_all(d);
  return r;
}

std::vector<nlohmann::json> errors(const Ran& r) {
  std::vector<nlohmann::json> e;
  for (const auto& x : r.events)
    if (x["ev"] == "error") e.push_back(x);
  return e;
}

TEST(HomingCli, TheDryRunAssumesAHomedMachine) {
  const Ran r = run_homing("move.nc", "", "homed");
  EXPECT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_TRUE(errors(r).empty());
  const auto& x = r.final_state["channels"][0]["axes"]["X"];
  EXPECT_EQ(x["homed"], true);
  EXPECT_DOUBLE_EQ(x["mcs"].get<double>(), 40.0);
}

TEST(HomingCli, UnhomedTheMoveOfXIsRefusedWithTheIdAndLine) {
  const Ran r = run_homing("move.nc", "--unhomed", "unhomed");
  EXPECT_NE(r.cli.exit_code, 0) << r.cli.output;
  const auto e = errors(r);
  ASSERT_EQ(e.size(), 1u) << r.cli.output;
  EXPECT_EQ(e[0]["id"], 930740);
  EXPECT_EQ(e[0]["line"], 2);
  EXPECT_NE(e[0]["msg"].get<std::string>().find("axis X is not homed"), std::string::npos) << e[0].dump();
  const auto& axes = r.final_state["channels"][0]["axes"];
  EXPECT_EQ(axes["X"]["homed"], false);
  EXPECT_EQ(axes["X"]["mcs"].get<double>(), 0.0);  // refused before it moved
  EXPECT_NE(r.cli.output.find("930740"), std::string::npos);
}

TEST(HomingCli, UnhomedG74HomesAndTheProgramRuns) {
  const Ran r = run_homing("home_then_move.nc", "--unhomed", "g74");
  EXPECT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_TRUE(errors(r).empty());
  const auto& axes = r.final_state["channels"][0]["axes"];
  EXPECT_EQ(axes["X"]["homed"], true);
  EXPECT_EQ(axes["Z"]["homed"], true);
  EXPECT_EQ(axes["Y"]["homed"], false);  // no G74 for Y, which needs none and moved unhomed
  EXPECT_DOUBLE_EQ(axes["Y"]["mcs"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(axes["X"]["mcs"].get<double>(), 40.0);
}

TEST(HomingCli, AMachineWithoutTheSettingWritesNoHomedField) {
  // examples/mill sets P-AXIS-00277 nowhere: its final state stays as it was.
  const auto d = temp_dir("homing_mill");
  const CliResult r = run_nck("run " + mill() + " " + mill() + "/contour.nc --final " + (d / "f.json").string() +
                              " --no-progress --unhomed");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::ifstream f(d / "f.json");
  const auto j = nlohmann::json::parse(f, nullptr, false);
  EXPECT_FALSE(j["channels"][0]["axes"]["X"].contains("homed"));
  std::filesystem::remove_all(d);
}

}  // namespace
}  // namespace nck::app::testing
