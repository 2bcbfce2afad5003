// #TOOL PREP [basic, sister, variant] is the T word's form (TF5200 #TOOL PREP): the
// PLC gets a T output with the basic number, as for T5.
#include <gtest/gtest.h>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

TEST(ToolPrep, OutputsTheBasicNumberLikeATWord) {
  const auto dir = temp_dir("tool_prep");
  std::ofstream(dir / "p.nc") << "N10 P10 = 7\nN20 #TOOL PREP [P10, 2, ]\nN30 T5\nN40 M30\n";
  CliResult r = run_nck("run " + root() + "/examples/mill " + (dir / "p.nc").string() + " --events " +
                        (dir / "e.jsonl").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<std::pair<std::string, int>> tools;  // T output, line of the block that gave it
  int line = 0;
  for (const nlohmann::json& e : read_jsonl(dir / "e.jsonl")) {
    if (e["ev"] == "block") line = e["line"].get<int>();
    if (e["ev"] == "plc_out" && e["fn"].get<std::string>().starts_with("T"))
      tools.emplace_back(e["fn"].get<std::string>(), line);
  }
  const std::vector<std::pair<std::string, int>> expected{{"T7", 2}, {"T5", 3}};
  EXPECT_EQ(tools, expected);
}

}  // namespace
}  // namespace nck::app::testing
