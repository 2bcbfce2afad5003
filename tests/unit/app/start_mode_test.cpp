// P-CHAN-00507 / P-CHAN-00508: a decoder function enabled only for one
// start mode (fct_condition[i]) acts only when the run starts in that mode.
// `nck run` is the standard start (ISG_STANDARD); --start-mode names another
// (docs/cli.md). Distance control on the cutter is the function that shows.
#include <gtest/gtest.h>

#include <string>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

// The cutter with FCT_3D_DIST_CTRL only in fct_enable[0] under `condition`,
// and a program switching distance control on.
struct ModeRun {
  CliResult r;
  std::vector<nlohmann::json> events;
};

ModeRun run_with_condition(const std::string& name, const std::string& condition, const std::string& args = "") {
  PatchedMachine m = patched_example("cutter", name, "channel1.lis", "");
  std::string text = read_file(m.dir / "channel1.lis");
  const std::string from = "configuration.decoder.function    FCT_3D_DIST_CTRL";
  text.replace(text.find(from), from.size(),
               "configuration.decoder.fct_enable[0]    FCT_3D_DIST_CTRL\n"
               "configuration.decoder.fct_condition[0] " + condition);
  std::ofstream(m.dir / "channel1.lis") << text;
  std::ofstream(m.dir / "p.nc") << "G0 X0 Y0 Z1.5\n#DIST CTRL ON [SURFACE SET_POS=0]\nG4 X0.1\nM30\n";
  ModeRun run;
  run.r = run_nck("run " + m.dir.string() + " " + (m.dir / "p.nc").string() + " --events " +
                  (m.dir / "e.jsonl").string() + " " + args);
  if (std::filesystem::exists(m.dir / "e.jsonl")) run.events = read_jsonl(m.dir / "e.jsonl");
  return run;
}

bool has_event(const ModeRun& r, const std::string& ev, const std::string& key, const nlohmann::json& value) {
  for (const auto& e : r.events)
    if (e["ev"] == ev && e.contains(key) && e[key] == value) return true;
  return false;
}

TEST(StartMode, AFunctionForDryRunIsOffInAPlainRun) {
  const ModeRun plain = run_with_condition("fct_dry_plain", "DRY_RUN");
  EXPECT_EQ(plain.r.exit_code, 1) << plain.r.output;
  EXPECT_TRUE(has_event(plain, "error", "id", 310015)) << plain.r.output;
  EXPECT_FALSE(has_event(plain, "dist_ctrl", "state", "ACTIVE"));

  const ModeRun dry = run_with_condition("fct_dry_on", "MACHINE_LOCK", "--start-mode DRY_RUN");  // synonyms
  EXPECT_EQ(dry.r.exit_code, 0) << dry.r.output;
  EXPECT_TRUE(has_event(dry, "dist_ctrl", "state", "ACTIVE")) << dry.r.output;
}

TEST(StartMode, BlockSearchFunctionsAreOffWithoutABlockSearch) {
  const ModeRun sv = run_with_condition("fct_sv", "SV");
  EXPECT_EQ(sv.r.exit_code, 1) << sv.r.output;
  EXPECT_TRUE(has_event(sv, "error", "id", 310015)) << sv.r.output;
  // SV belongs to a block search: asked for without one, it is bad usage ...
  const ModeRun asked = run_with_condition("fct_sv_asked", "SV", "--start-mode BLOCK_SEARCH");
  EXPECT_EQ(asked.r.exit_code, 2) << asked.r.output;
  EXPECT_NE(asked.r.output.find("block search"), std::string::npos) << asked.r.output;
}

// ... and a run with a block search is in start mode SV from its start.
TEST(StartMode, BlockSearchFunctionsActInABlockSearch) {
  const ModeRun searched = run_with_condition("fct_sv_search", "SV", "--start-at-block 1");
  EXPECT_EQ(searched.r.exit_code, 0) << searched.r.output;
  EXPECT_TRUE(has_event(searched, "dist_ctrl", "state", "ACTIVE")) << searched.r.output;
}

TEST(StartMode, StandardConditionActsInAPlainRun) {
  const ModeRun standard = run_with_condition("fct_standard", "ISG_STANDARD");
  EXPECT_EQ(standard.r.exit_code, 0) << standard.r.output;
  EXPECT_TRUE(has_event(standard, "dist_ctrl", "state", "ACTIVE"));
  // ... and not in another start mode.
  const ModeRun other = run_with_condition("fct_standard_dry", "ISG_STANDARD", "--start-mode DRY_RUN");
  EXPECT_EQ(other.r.exit_code, 1) << other.r.output;
  EXPECT_TRUE(has_event(other, "error", "id", 310015));
}

TEST(StartMode, UnknownModeIsBadUsage) {
  const ModeRun r = run_with_condition("fct_unknown", "DRY_RUN", "--start-mode FAST");
  EXPECT_EQ(r.r.exit_code, 2) << r.r.output;
  EXPECT_NE(r.r.output.find("940001"), std::string::npos) << r.r.output;
}

}  // namespace
}  // namespace nck::app::testing
