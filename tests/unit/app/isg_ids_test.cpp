// TF5200 readings through the nck binary (issue 44, items 8 and 11): block
// numbers from expressions, and the ISG diagnosis IDs where the manual gives
// one (skip level 21655, #SLOPE type 21629, an axis twice 20203 unless
// P-CHAN-00148 allows it), with nck's earlier IDs findable by `nck errors`.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

std::filesystem::path program(const std::string& name, const std::string& text) {
  return write(temp_dir("ids-" + name) / "main.nc", text);
}

// The N of every block `nck parse --json` prints, in order.
std::vector<long> block_numbers(const CliResult& r) {
  std::vector<long> out;
  for (const std::string& line : split(r.output, '\n')) {
    if (line.empty() || line[0] != '{') continue;
    const json b = json::parse(line);
    if (b.contains("n") && !b["n"].is_null()) out.push_back(b["n"].get<long>());
  }
  return out;
}

// TF5200 "NC block numbers": an expression's value is rounded to an integer.
TEST(IsgBlockNumbers, ExpressionsAreRounded) {
  const CliResult r = run_nck_raw("parse --json " +
                                  program("n", "P123 = 7.5\nNP123 G0 X1\n$FOR P1 = 1, 3, 1\nN[P1*100] X[P1]\n$ENDFOR\n"
                                               "N[2.4] X0\nM30\n").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(block_numbers(r), (std::vector<long>{8, 100, 200, 300, 2}));
}

TEST(IsgBlockNumbers, NegativeStaysAnError) {
  const CliResult r = run_nck("parse " + program("n-neg", "N[-3] X1\nM30\n").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("main.nc:1:1: error 920009"), std::string::npos) << r.output;
}

// TF5200 "Extended skipping": levels 1..10, anything else 21655.
TEST(IsgIds, SkipLevelBeyondTenIs21655) {
  const CliResult r = run_nck("parse " + program("skip", "G0 X0\n/11 G0 X1\nM30\n").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("main.nc:2:1: error 21655"), std::string::npos) << r.output;
}

TEST(IsgIds, UnknownSlopeTypeIs21629) {
  const CliResult r = run_nck("parse " + program("slope", "#SLOPE [TYPE=JERKY]\nM30\n").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("main.nc:1:14: error 21629"), std::string::npos) << r.output;
}

TEST(IsgIds, AxisTwiceInABlockIs20203) {
  const CliResult r = run_nck("parse " + program("twice", "G0 X10 Y20 X10\nM30\n").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("main.nc:1:12: error 20203"), std::string::npos) << r.output;
}

// P-CHAN-00148 (with P-CHAN-00116, which it needs) allows an axis several
// times: under G90 the last value counts, under G91 they add up.
TEST(IsgIds, MultiAxesInBlockAllowsAnAxisTwice) {
  const PatchedMachine m = patched_example("mill", "multi-axes", "channel1.lis",
                                           "multi_dimension_in_block 1\nmulti_axes_in_block 1");
  const auto prog = program("multi", "G90 G0 X10 Y10 X2\nG91 Y5 Y1\nM30\n");
  const auto fin = prog.parent_path() / "f.json";
  const CliResult r = run_nck("run " + m.dir.string() + " " + prog.string() + " --final " + fin.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json f = json::parse(read_file(fin));
  EXPECT_NEAR(f["channels"][0]["axes"]["X"]["pcs"].get<double>(), 2, 1e-9);
  EXPECT_NEAR(f["channels"][0]["axes"]["Y"]["pcs"].get<double>(), 16, 1e-9);
}

// Without P-CHAN-00116 the manual corrects P-CHAN-00148 to 0 (21404).
TEST(IsgIds, MultiAxesWithoutMultiDimensionIs21404) {
  const PatchedMachine m = patched_example("mill", "multi-axes-alone", "channel1.lis", "multi_axes_in_block 1");
  const CliResult r = run_nck("check " + m.dir.string() + " " + program("alone", "G0 X1 X2\nM30\n").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find(fmt::format("channel1.lis:{}", m.line)), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("warning 21404"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("error 20203"), std::string::npos) << r.output;
}

// nck's own IDs of before stay findable, and ISG's alternative IDs too.
TEST(IsgIds, ErrorsFindsAliases) {
  for (auto [alias, id] : {std::pair{"920012", "| 21655 |"}, {"920200", "| 21629 |"},
                           {"70330", "| 310019 |"}, {"70576", "| 310020 |"}}) {
    const CliResult r = run_nck(std::string("errors ") + alias);
    EXPECT_EQ(r.exit_code, 0) << alias << "\n" << r.output;
    EXPECT_NE(r.output.find(id), std::string::npos) << alias << "\n" << r.output;
  }
}

}  // namespace
}  // namespace nck::app
