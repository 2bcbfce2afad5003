// The `trc` event (issue 13) through `nck run`: tool radius compensation
// selected, deselected, its side or its D changed while active, with the
// state, D, tool radius, channel and line of the block that programs it.
#include <gtest/gtest.h>

#include "trc_helpers.hpp"

namespace nck::app {
namespace {

using namespace trc_testing;

// The time of the block event of `line`.
double block_time(const TrcRun& r, int line) {
  for (const json& e : r.events)
    if (e["ev"] == "block" && e["line"] == line) return e["t"];
  ADD_FAILURE() << "no block event for line " << line;
  return -1;
}

struct Expected {
  int line;
  std::string state;
  int d;
  double radius_mm;
};

void expect_trc_events(const TrcRun& r, const std::vector<Expected>& want) {
  ASSERT_EQ(r.trc_events.size(), want.size()) << r.cli.output;
  for (std::size_t i = 0; i < want.size(); ++i) {
    const json& e = r.trc_events[i];
    EXPECT_EQ(e["ch"], 1);
    EXPECT_EQ(e["line"], want[i].line);
    EXPECT_EQ(e["state"], want[i].state) << "line " << want[i].line;
    EXPECT_EQ(e["d"], want[i].d) << "line " << want[i].line;
    EXPECT_DOUBLE_EQ(e["radius_mm"].get<double>(), want[i].radius_mm) << "line " << want[i].line;
    EXPECT_TRUE(e["file"].get<std::string>().ends_with("p.nc"));
    // With the block that programs it.
    EXPECT_DOUBLE_EQ(e["t"].get<double>(), block_time(r, want[i].line)) << "line " << want[i].line;
  }
}

TEST(TrcEvent, SelectionNewDSideChangeAndDeselection) {
  // mill tools: D1 5 mm, D2 4.25 mm. D1 again under G40 is no event.
  const TrcRun r = run_text("mill", "trc-events",
                            "N10 G17 G90 D1\nN20 G0 X-10 Y-10\nN30 G41 G1 X0 Y0 F600\nN40 X20\nN50 D2 X30\n"
                            "N60 G42 X40\nN70 X50\nN80 G40 G1 Y-10\nN90 D1\nN100 M30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  expect_trc_events(r, {{3, "G41", 1, 5.0}, {5, "G41", 2, 4.25}, {6, "G42", 2, 4.25}, {8, "G40", 2, 4.25}});
  // The path agrees: D2 on the left at Y4.25, then on the right at Y-4.25.
  expect_points(r, "X", "Y", {{60, 30, 4.25}, {70, 40, -4.25}, {80, 50, -4.25}});
}

TEST(TrcEvent, ProgrammedWithoutMotionReportsItsOwnBlock) {
  // G41 alone: the compensation acts at the next plane motion, the event
  // belongs to the block that programs it.
  const TrcRun r = run_text("mill", "trc-events-alone",
                            "N10 G17 G90 D1\nN20 G0 X-10 Y-10\nN30 G41\nN40 G1 X0 Y0 F600\nN50 X20\n"
                            "N60 G40\nN70 G1 Y-10\nN80 M30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  expect_trc_events(r, {{3, "G41", 1, 5.0}, {6, "G40", 1, 5.0}});
  expect_points(r, "X", "Y", {{50, 0, 5}, {60, 20, 5}, {80, 20, -10}});
}

}  // namespace
}  // namespace nck::app
