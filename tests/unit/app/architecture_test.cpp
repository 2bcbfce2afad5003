// The behaviour that the architecture step (prep pipeline, sim layer)
// changed on purpose, through the nck binary: M1 follows the HLI's
// optional-stop switch, 310015 comes from the machine data, and a fixed
// buffer that would overflow is an error with an ID.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

std::vector<double> stop_times(const std::filesystem::path& events) {
  std::vector<double> t;
  for (const auto& e : read_jsonl(events))
    if (e["ev"] == "stop") t.push_back(e["t"].get<double>());
  return t;
}

// M0 always stops; M1 only while the PLC has the optional-stop switch on
// (HLI channel control optional_stop, switched by the scenario at 0.05 s).
TEST(ArchitectureStep, OptionalStopM1FollowsTheHliSwitch) {
  const auto dir = temp_dir("optional_stop");
  std::ofstream(dir / "p.nc") << "N10 M1\nN20 M0\nN30 G4 X0.1\nN40 M1\nN50 M30\n";
  const std::string run = "run " + root() + "/examples/mill " + (dir / "p.nc").string() + " --events ";
  CliResult off = run_nck(run + (dir / "off.jsonl").string());
  ASSERT_EQ(off.exit_code, 0) << off.output;
  EXPECT_EQ(stop_times(dir / "off.jsonl"), std::vector<double>{0.0});  // M0 only

  std::ofstream(dir / "on.plc") << "0.05 optional_stop on\n";
  CliResult on = run_nck(run + (dir / "on.jsonl").string() + " --plc " + (dir / "on.plc").string());
  ASSERT_EQ(on.exit_code, 0) << on.output;
  EXPECT_EQ(stop_times(dir / "on.jsonl"), (std::vector<double>{0.0, 0.1}));  // M0, then N40's M1
}

// The lathe example's channel list does not set FCT_3D_DIST_CTRL (the mill's does).
TEST(ArchitectureStep, DistanceControlWithoutTheFunctionFlagIs310015) {
  const auto dir = temp_dir("dist_ctrl_flag");
  std::ofstream(dir / "p.nc") << "N10 G0 X0\nN20 #DIST CTRL ON [SURFACE SET_POS=1]\nN30 M30\n";
  CliResult r = run_nck("run " + root() + "/examples/lathe " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  bool found = false;
  for (const auto& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "error") {
      EXPECT_EQ(e["id"], 310015);
      EXPECT_EQ(e["line"], 2);
      found = true;
    }
  EXPECT_TRUE(found);
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
TEST(ArchitectureStep, TooManyLateWaitsIsAnErrorNotALostWait) {
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
TEST(ArchitectureStep, SixteenLateWaitsFit) {
  const auto m = late_waits("late_waits_fit", 16);
  CliResult r = run_nck("run " + m.dir.string() + " " + (m.dir / "p.nc").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

}  // namespace
}  // namespace nck::app::testing
