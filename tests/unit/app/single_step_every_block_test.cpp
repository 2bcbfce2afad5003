// Single step with P-CHAN-00015 = 1 holds after every block (issue 44,
// item 6; TF5200 single-step page), also after a block that only assigns a
// parameter; a comment line passes. Each of them gets its block event.
// Before, the assignment blocks vanished: no block event and no hold.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;

TEST(SingleStepEveryBlock, AssignmentBlocksHoldAndHaveTheirBlockEvents) {
  const PatchedMachine m = patched_example("mill", "step-every", "channel1.lis", "einzelschrittmodus 1");
  const auto dir = temp_dir("step-every-run");
  write(dir / "p.nc", "N10 G90 G1 X10 F600\nN20 P1 = 5\nN30 P2 = P1 + 1\n; a comment\nN40 X[P2 * 3]\nN50 M30\n");
  std::string plc = "0 auto_cycle_start off\n0 single_step on\n";
  for (int i = 1; i <= 8; ++i) plc += std::to_string(2 * i) + ".0 cycle_start\n";
  write(dir / "s.plc", plc);
  const CliResult c = run_nck("run " + m.dir.string() + " " + (dir / "p.nc").string() + " --plc " +
                              (dir / "s.plc").string() + " --events " + (dir / "e.jsonl").string() + " --final " +
                              (dir / "f.json").string());
  ASSERT_EQ(c.exit_code, 0) << c.output;
  std::vector<long> blocks, holds;
  for (const nlohmann::json& e : read_jsonl(dir / "e.jsonl")) {
    if (e["ev"] == "block") blocks.push_back(e["line"].get<long>());
    if (e["ev"] == "state" && e["to"] == "hold" && e["reason"] == "single_step") holds.push_back(e["line"].get<long>());
  }
  EXPECT_EQ(blocks, (std::vector<long>{1, 2, 3, 5, 6}));
  EXPECT_EQ(holds, (std::vector<long>{1, 2, 3, 5}));
  const auto final_state = nlohmann::json::parse(read_file(dir / "f.json"));
  EXPECT_DOUBLE_EQ(final_state["channels"][0]["axes"]["X"]["mcs"].get<double>(), 18.0);  // P2 = 6
}

}  // namespace
}  // namespace nck::app
