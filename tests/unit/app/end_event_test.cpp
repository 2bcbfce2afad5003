// `end` is each channel's last event (docs/outputs.md), also when an error aborts
// the program while its spindles are turning or fail (the spindle events
// the abort causes come before `end`).
#include <gtest/gtest.h>

#include <string>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

// Events of channel `ch` after its `end` (the event lines as text).
std::vector<std::string> events_after_end(const std::vector<nlohmann::json>& events, int ch) {
  std::vector<std::string> after;
  bool ended = false;
  for (const nlohmann::json& e : events) {
    if (!e.contains("ch") || e["ch"] != ch) continue;
    if (ended) after.push_back(e.dump());
    if (e["ev"] == "end") ended = true;
  }
  EXPECT_TRUE(ended);
  return after;
}

std::vector<nlohmann::json> run_on(const PatchedMachine& m, const std::string& program, int expected_exit) {
  std::ofstream(m.dir / "p.nc") << program;
  const CliResult r = run_nck("run " + m.dir.string() + " " + (m.dir / "p.nc").string() + " --events " +
                              (m.dir / "e.jsonl").string());
  EXPECT_EQ(r.exit_code, expected_exit) << r.output;
  return read_jsonl(m.dir / "e.jsonl");
}

TEST(EndEvent, ComesAfterTheSpindleErrorOfAForbiddenDirection) {
  // kenngr.vorz_richtung 1 / beweg_richt 1: M4 is forbidden (60254).
  const auto m = patched_example("mill", "end_pref", "s1.lis", "kenngr.vorz_richtung 1\nkenngr.beweg_richt 1\n");
  const auto events = run_on(m, "N10 S500 M4\nN20 M30\n", 1);
  EXPECT_EQ(events_after_end(events, 1), std::vector<std::string>{});
  bool spindle_error = false;  // the spindle's error state is still reported, before `end`
  for (const auto& e : events) spindle_error = spindle_error || (e["ev"] == "spindle" && e["mode"] == "error");
  EXPECT_TRUE(spindle_error);
}

TEST(EndEvent, ComesAfterTheSpindleStopsOfAnAbort) {
  // An NC error while S1 turns: the abort stops the spindle.
  const auto m = patched_example("mill", "end_abort", "sim.lis", "");
  const auto events = run_on(m, "N10 S500 M3\nN20 G4 X0.3\nN30 G1 X10 F0\nN40 M30\n", 1);
  EXPECT_EQ(events_after_end(events, 1), std::vector<std::string>{});
}

}  // namespace
}  // namespace nck::app::testing
