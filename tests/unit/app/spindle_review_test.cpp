// Spindle defects of the acceptance review (issue 9), each through `nck run`
// on the mill example: numbers from the seed FCT-S1 or computed by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

struct ReviewRun {
  int exit_code = -1;
  std::string output;
  std::vector<json> events;
  std::filesystem::path dir;
  json final_state;
  // column name -> values of every traced cycle
  std::map<std::string, std::vector<double>> trace;
};

std::map<std::string, std::vector<double>> read_trace(const std::filesystem::path& csv) {
  std::map<std::string, std::vector<double>> cols;
  const auto lines = split(read_file(csv), '\n');
  if (lines.empty()) return cols;
  const auto header = split(lines[0], ',');
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto cells = split(lines[i], ',');
    for (std::size_t j = 0; j < cells.size() && j < header.size(); ++j)
      if (!cells[j].empty()) cols[header[j]].push_back(std::stod(cells[j]));
  }
  return cols;
}

// Runs `program_text` on `machine` with events, an every-cycle trace and --final.
ReviewRun run(const std::filesystem::path& machine, const std::string& program_text, const std::string& args = "") {
  ReviewRun r;
  r.dir = temp_dir("review");
  std::ofstream(r.dir / "p.nc") << program_text;
  const CliResult c = run_nck("run " + machine.string() + " " + (r.dir / "p.nc").string() + " --events " +
                              (r.dir / "e.jsonl").string() + " --trace " + (r.dir / "t.csv").string() +
                              " --final " + (r.dir / "f.json").string() + " " + args);
  r.exit_code = c.exit_code;
  r.output = c.output;
  r.events = read_jsonl(r.dir / "e.jsonl");
  const std::string final_text = read_file(r.dir / "f.json");
  if (!final_text.empty()) r.final_state = json::parse(final_text);
  r.trace = read_trace(r.dir / "t.csv");
  return r;
}

std::filesystem::path mill() { return root() + "/examples/mill"; }

std::filesystem::path mill_with(const std::string& name, const std::string& file, const std::string& lines) {
  return patched_example("mill", name, file, lines).dir;
}

std::vector<json> of_kind(const std::vector<json>& events, const std::string& ev, const std::string& spindle) {
  std::vector<json> out;
  std::copy_if(events.begin(), events.end(), std::back_inserter(out),
               [&](const json& e) { return e["ev"] == ev && e.value("spindle", json()) == spindle; });
  return out;
}

std::vector<std::string> modes(const std::vector<json>& events, const std::string& spindle) {
  std::vector<std::string> out;
  for (const json& e : of_kind(events, "spindle", spindle)) out.push_back(e["mode"]);
  return out;
}

// Item 15, seed 2.9: --final lists the spindle's HLI objects, named after
// the facts sheet's paths. 200 rpm = 1200 deg/s = 1200000 in 0.001 deg/s.
TEST(SpindleReview, FinalStateListsTheSeedsHliSpindleObjects) {
  const ReviewRun rot = run(mill(), "%h\nN10 S200 M3\nN20 G4 X0.5\nN30 M30\n");
  ASSERT_EQ(rot.exit_code, 0) << rot.output;
  const json& a = rot.final_state["hli"]["spindles"]["S1"];
  EXPECT_EQ(a["cmd_rev_r"], 1200000);
  EXPECT_EQ(a["rev_control_aktiv_r"], true);
  EXPECT_EQ(a["speed_monitoring_invalid"], false);
  EXPECT_EQ(a["command_error"], false);
  EXPECT_EQ(a["distance_to_go"], 0);
  // M19 at 10 rpm (60 deg/s) to 180 deg, stopped after 1 s: about 120 deg to go.
  const ReviewRun pos = run(mill(), "%h\nN10 M19 S.POS=180 S10\nN20 M30\n", "--max-time 1");
  EXPECT_EQ(pos.exit_code, 1) << pos.output;
  const json& b = pos.final_state["hli"]["spindles"]["S1"];
  EXPECT_EQ(b["target_pos"], 1800000);
  EXPECT_NEAR(b["distance_to_go"].get<double>(), 1200000, 2000);
  EXPECT_EQ(b["rev_control_aktiv_r"], false);
}

}  // namespace
}  // namespace nck::app
