// nck run --stop-at (issue 27): the mark's forms, a bad mark, and a run of
// the mill's contour ending where its block ends with the state of a full
// run at that point.
#include <gtest/gtest.h>

#include "nck/run/stop_at.hpp"
#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using K = kernel::StopMark::Kind;

TEST(StopAt, MarksParse) {
  EXPECT_EQ(parse_stop_at("N200")->mark, (kernel::StopMark{K::n, 200}));
  EXPECT_EQ(parse_stop_at("n0")->mark, (kernel::StopMark{K::n, 0}));
  EXPECT_EQ(parse_stop_at("line:12")->mark, (kernel::StopMark{K::line, 12}));
  EXPECT_EQ(parse_stop_at("block:3")->mark, (kernel::StopMark{K::block, 3}));
  const auto e = parse_stop_at("event:wait");
  ASSERT_TRUE(e && e->event);
  EXPECT_EQ(*e->event, kernel::EventKind::wait);
  EXPECT_EQ(e->mark.kind, K::none);
  for (const char* bad : {"", "N", "N-1", "N1.5", "X10", "line:0", "line:", "block:0", "block:x", "event:", "event:nope",
                          "N99999999999999999999"})
    EXPECT_FALSE(parse_stop_at(bad)) << bad;
}

TEST(StopAt, ABadMarkIsAUsageError) {
  const CliResult r = run_nck("run " + mill() + " " + mill() + "/contour.nc --no-progress --stop-at X10");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("no stop mark"), std::string::npos) << r.output;
}

// contour.nc up to its second block (N20 G0 X0 Y0 Z10; N10 is the first):
// the run ends where that block ends, the final state there.
TEST(StopAt, ContourEndsWhereItsSecondBlockEnds) {
  const auto dir = temp_dir("stop_at_contour");
  const CliResult r = run_nck("run " + mill() + " " + mill() + "/contour.nc --no-progress --stop-at block:2 --final " +
                              (dir / "f.json").string() + " --events " + (dir / "e.jsonl").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json f = nlohmann::json::parse(read_file(dir / "f.json"));
  EXPECT_EQ(f["end"], "stop_at");
  // N20 G0 X0 Y0 Z10: where the full run stands when N20 ends
  const nlohmann::json& axes = f["channels"][0]["axes"];
  EXPECT_NEAR(axes["X"]["mcs"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(axes["Y"]["mcs"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(axes["Z"]["mcs"].get<double>(), 10.0, 1e-9);
  std::size_t blocks = 0;
  const auto events = read_jsonl(dir / "e.jsonl");
  for (const nlohmann::json& e : events) blocks += e["ev"] == "block";
  EXPECT_EQ(blocks, 2u);
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.back()["ev"], "end");
  EXPECT_EQ(events.back()["reason"], "stop_at");
}

}  // namespace
}  // namespace nck::app
