// nck run --start-at (issue 27, block search types 1, 3 and 4): nothing
// moves before the mark, the axes return to the contour in a straight line,
// the run ends in the state of a full run, and the path after the restart
// is the full run's path (positions by arc length, within 1 um).
#include <gtest/gtest.h>

#include "nck/run/start_at.hpp"
#include "cli_helpers.hpp"

namespace nck::app {
namespace {

using namespace testing;
using Kind = prep::SearchMark::Kind;
using Point = std::array<double, 3>;

TEST(BlockSearch, MarksParse) {
  auto m = parse_start_at("N100");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->kind, Kind::block_number);
  EXPECT_EQ(m->value, 100);
  EXPECT_EQ(m->pass, 1u);
  m = parse_start_at("n230:3@contour.nc");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->value, 230);
  EXPECT_EQ(m->pass, 3u);
  EXPECT_EQ(m->program, "contour.nc");
  m = parse_start_at_offset("542:2");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->kind, Kind::file_offset);
  EXPECT_EQ(m->value, 542);
  EXPECT_EQ(m->pass, 2u);
  m = parse_start_at_block("17");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->kind, Kind::block_counter);
  EXPECT_EQ(m->value, 17);
  for (const char* bad : {"", "N", "100", "N-1", "N10:0", "N10:", "N10@", "Nx", "N1.5"})
    EXPECT_FALSE(parse_start_at(bad)) << bad;
  for (const char* bad : {"", "-1", "1:0", "x", "5@"}) EXPECT_FALSE(parse_start_at_offset(bad)) << bad;
  for (const char* bad : {"", "0", "-3", "2:1"}) EXPECT_FALSE(parse_start_at_block(bad)) << bad;
}

struct SearchedRun {
  CliResult result;
  std::vector<nlohmann::json> events;
  nlohmann::json final;
  std::vector<std::pair<double, Point>> trace;  // t, X Y Z
};

SearchedRun run_contour(const std::string& name, const std::string& args, const std::string& program = "contour.nc") {
  const auto dir = temp_dir("block_search_" + name);
  SearchedRun r;
  r.result = run_nck("run " + mill() + " " + mill() + "/" + program + " --no-progress " + args + " --events " +
                     (dir / "e.jsonl").string() + " --final " + (dir / "f.json").string() + " --trace " +
                     (dir / "t.csv").string());
  r.events = read_jsonl(dir / "e.jsonl");
  r.final = nlohmann::json::parse(read_file(dir / "f.json"));
  const std::vector<std::string> lines = split(read_file(dir / "t.csv"), '\n');
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> c = split(lines[i], ',');
    if (c.size() < 4) continue;
    r.trace.push_back({std::stod(c[0]), Point{std::stod(c[1]), std::stod(c[2]), std::stod(c[3])}});
  }
  return r;
}

double time_of_block(const SearchedRun& r, long n) {
  for (const nlohmann::json& e : r.events)
    if (e["ev"] == "block" && e["n"] == n) return e["t"].get<double>();
  return -1;
}

double dist(const Point& a, const Point& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// Distance from p to the segment a-b.
double to_segment(const Point& p, const Point& a, const Point& b) {
  Point ab{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  double u = len2 > 0 ? ((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1] + (p[2] - a[2]) * ab[2]) / len2 : 0;
  u = std::clamp(u, 0.0, 1.0);
  return dist(p, Point{a[0] + u * ab[0], a[1] + u * ab[1], a[2] + u * ab[2]});
}

// The points of the trace from time t0 on, without repeats (standstill).
std::vector<Point> path_from(const SearchedRun& r, double t0) {
  std::vector<Point> out;
  for (const auto& [t, p] : r.trace)
    if (t >= t0 - 1e-9 && (out.empty() || dist(out.back(), p) > 0)) out.push_back(p);
  return out;
}

// A point where the path turns (a block transition at a corner): the
// sampled polylines of two runs cut such a corner differently.
bool turns_at(const std::vector<Point>& path, std::size_t i) {
  if (i == 0 || i + 1 >= path.size()) return true;
  const Point& a = path[i - 1];
  const Point& b = path[i];
  const Point& c = path[i + 1];
  const double dot = (b[0] - a[0]) * (c[0] - b[0]) + (b[1] - a[1]) * (c[1] - b[1]) + (b[2] - a[2]) * (c[2] - b[2]);
  return dot < std::cos(2.0 * 3.14159265358979 / 180.0) * dist(a, b) * dist(b, c);
}

// Every point of `restarted` lies on the full run's path, and both go the
// same length: the same path, positions compared by arc length.
void expect_same_path(const std::vector<Point>& full, const std::vector<Point>& restarted) {
  ASSERT_GT(full.size(), 10u);
  ASSERT_GT(restarted.size(), 10u);
  double len_full = 0, len_restarted = 0;
  for (std::size_t i = 1; i < full.size(); ++i) len_full += dist(full[i - 1], full[i]);
  for (std::size_t i = 1; i < restarted.size(); ++i) len_restarted += dist(restarted[i - 1], restarted[i]);
  EXPECT_NEAR(len_restarted, len_full, 0.05);  // the polylines cut the corners a little differently
  std::size_t k = 0, compared = 0;  // the full run's segment near the point
  for (std::size_t i = 0; i < restarted.size(); ++i) {
    if (turns_at(restarted, i)) continue;
    double best = 1e9;
    std::size_t best_k = k;
    for (std::size_t j = k; j + 1 < full.size() && j < k + 4000; ++j) {
      const double d = to_segment(restarted[i], full[j], full[j + 1]);
      if (d < best) best = d, best_k = j;
      if (d < 1e-7) break;
    }
    k = best_k;
    // a chord that cuts a corner (e.g. rapid to feed) is no place on the path
    if (turns_at(full, best_k) || turns_at(full, best_k + 1)) continue;
    ++compared;
    EXPECT_LT(best, 1e-3) << "point " << i << " of " << restarted.size();  // 1 um
    if (best >= 1e-3) return;
  }
  EXPECT_GT(compared, restarted.size() / 2);
}

// contour.nc restarted at N100 with 40 % of it covered: nothing moves before
// the return, the return is a straight rapid line from where the axes stand
// (the origin) to 40 % along N100, the rest of the program runs the full
// run's path and ends in its state.
TEST(BlockSearch, ContourFromN100EndsAsTheFullRun) {
  const SearchedRun full = run_contour("full", "");
  const SearchedRun r = run_contour("n100", "--start-at N100 --covered 40");
  ASSERT_EQ(r.result.exit_code, 0) << r.result.output;
  // no block before N100 ran
  for (const nlohmann::json& e : r.events)
    if (e["ev"] == "block") {
      EXPECT_EQ(e["n"], 100) << e.dump();
      break;
    }
  // states: idle -> searching -> returning -> hold -> running (cycle start)
  std::vector<std::string> states;
  for (const nlohmann::json& e : r.events)
    if (e["ev"] == "state") states.push_back(e["from"].get<std::string>() + ">" + e["to"].get<std::string>());
  ASSERT_GE(states.size(), 4u);
  EXPECT_EQ(states[0], "idle>searching");
  EXPECT_EQ(states[1], "searching>returning");
  EXPECT_EQ(states[2], "returning>hold");
  EXPECT_EQ(states[3], "hold>running");
  // the final state of the full run, to the bit (the time aside)
  nlohmann::json a = full.final, b = r.final;
  a.erase("time");
  b.erase("time");
  a.erase("time_by_cause");  // where the time went differs as the time does
  b.erase("time_by_cause");
  EXPECT_EQ(a, b);
  // N100 G1 Y[P2 - P3] from (-40, -17, -2) to (-40, 17, -2): 40 % is Y = -3.4
  const double t_restart = time_of_block(r, 100);
  ASSERT_GT(t_restart, 0);
  const Point restart{-40, -17 + 0.4 * 34, -2};
  const std::vector<Point> back = path_from(r, 0);
  for (const Point& p : back) {
    if (dist(p, restart) < 1e-9) break;
    EXPECT_LT(to_segment(p, Point{0, 0, 0}, restart), 1e-6);  // a straight line (the trace has 6 decimals)
  }
  // the path after the restart point: on the full run's path from there
  std::vector<Point> full_path = path_from(full, time_of_block(full, 100));
  while (!full_path.empty() && full_path.front()[1] < restart[1] - 1e-9) full_path.erase(full_path.begin());
  expect_same_path(full_path, path_from(r, t_restart));
}

// The state at the restart is the full run's at that block: searched to N150
// and stopped where N150 ends, the channel is in the state of a full run
// stopped there (modal state, offsets, positions).
TEST(BlockSearch, StateAtTheRestartIsTheFullRunsState) {
  const SearchedRun full = run_contour("stop_full", "--stop-at N150");
  const SearchedRun r = run_contour("stop_searched", "--start-at N150 --stop-at N150");
  ASSERT_EQ(r.result.exit_code, 0) << r.result.output;
  EXPECT_EQ(full.final["channels"], r.final["channels"]);
  // with tool radius compensation active at the mark (its offset contour)
  const SearchedRun trc_full = run_contour("trc_full", "--stop-at N140", "contour_trc.nc");
  const SearchedRun trc = run_contour("trc_searched", "--start-at N140 --stop-at N140", "contour_trc.nc");
  ASSERT_EQ(trc.result.exit_code, 0) << trc.result.output;
  EXPECT_EQ(trc_full.final["channels"], trc.final["channels"]);
}

// Every form of the mark finds N100 of contour.nc; a pass count finds the
// third pass of N230 in the hole loop.
TEST(BlockSearch, OffsetCounterAndPassFindTheirBlock) {
  const std::string text = read_file(mill() + "/contour.nc");
  const std::size_t offset = text.find("N100");
  const SearchedRun by_offset = run_contour("offset", "--start-at-offset " + std::to_string(offset));
  EXPECT_EQ(by_offset.result.exit_code, 0) << by_offset.result.output;
  EXPECT_GT(time_of_block(by_offset, 100), 0);
  EXPECT_LT(time_of_block(by_offset, 90), 0);
  const SearchedRun by_pass = run_contour("pass", "--start-at N230:3");
  EXPECT_EQ(by_pass.result.exit_code, 0) << by_pass.result.output;
  std::size_t n230 = 0;
  for (const nlohmann::json& e : by_pass.events) n230 += e["ev"] == "block" && e["n"] == 230;
  EXPECT_EQ(n230, 4u);  // passes 3..6 of the six holes
}

// The block counter counts the rows read: the restart block is the first
// one at or after it (nck parse --json shows every block's row).
TEST(BlockSearch, BlockCounterRestartsAtTheRowsBlock) {
  const CliResult parsed = run_nck_raw("parse " + mill() + "/contour.nc --json 2>/dev/null");
  ASSERT_EQ(parsed.exit_code, 0);
  long row = 0;
  for (const std::string& line : split(parsed.output, '\n')) {
    if (line.empty()) continue;
    const nlohmann::json b = nlohmann::json::parse(line);
    if (b["n"] == 120) row = b["row"].get<long>();
  }
  ASSERT_GT(row, 0);
  const SearchedRun r = run_contour("row", "--start-at-block " + std::to_string(row));
  EXPECT_EQ(r.result.exit_code, 0) << r.result.output;
  EXPECT_LT(time_of_block(r, 110), 0);
  EXPECT_GT(time_of_block(r, 120), 0);
}

// An unknown block number: a warning, the search runs to the program end,
// then error 20704. A pass count beyond the passes: 20704 alone.
TEST(BlockSearch, AMarkNeverFoundIs20704) {
  const SearchedRun unknown = run_contour("unknown", "--start-at N999");
  EXPECT_EQ(unknown.result.exit_code, 1);
  EXPECT_NE(unknown.result.output.find("warning 930700"), std::string::npos) << unknown.result.output;
  EXPECT_NE(unknown.result.output.find("error 20704"), std::string::npos) << unknown.result.output;
  const SearchedRun passes = run_contour("passes", "--start-at N100:2");
  EXPECT_EQ(passes.result.exit_code, 1);
  EXPECT_EQ(passes.result.output.find("930700"), std::string::npos) << passes.result.output;
  EXPECT_NE(passes.result.output.find("error 20704"), std::string::npos) << passes.result.output;
  for (const SearchedRun* r : {&unknown, &passes}) {
    EXPECT_EQ(r->final["end"], "error");
    EXPECT_EQ(r->trace.back().second, (Point{0, 0, 0}));  // nothing moved
  }
}

// The technology functions met in search reach the PLC before the return:
// spindle.nc restarted at N100 has S1 turning (M3, its last speed S3000)
// and S2 turning (M4 3000 rpm) before the axes move.
TEST(BlockSearch, FunctionsMetInSearchGoToThePlcFirst) {
  const SearchedRun r = run_contour("spindle", "--start-at N100", "spindle.nc");
  ASSERT_EQ(r.result.exit_code, 0) << r.result.output;
  double t_m3 = -1, t_return = -1;
  std::map<std::string, double> rpm;
  for (const nlohmann::json& e : r.events) {
    if (e["ev"] == "plc_out" && e["fn"] == "M3" && t_m3 < 0) t_m3 = e["t"].get<double>();
    if (e["ev"] == "state" && e["to"] == "returning") t_return = e["t"].get<double>();
    if (e["ev"] == "spindle" && t_return < 0) rpm[e["spindle"].get<std::string>()] = e["rpm"].get<double>();
  }
  EXPECT_GE(t_m3, 0);
  EXPECT_GT(t_return, t_m3);  // the M3 is acknowledged and S1 at speed first
  EXPECT_DOUBLE_EQ(rpm["S1"], 3000);
  EXPECT_DOUBLE_EQ(rpm["S2"], -3000);
}

TEST(BlockSearch, BadUsageIsRefused) {
  for (const std::string args : {"--covered 40", "--start-at X10", "--start-at N10 --covered 101",
                                 "--start-mode SV", "--start-at N10 --start-at-block 3"}) {
    const CliResult r = run_nck("run " + mill() + " " + mill() + "/contour.nc --no-progress " + args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.output;
  }
}

// A preparation thread searches the same way: the same events.
TEST(BlockSearch, PrepThreadSearchesTheSame) {
  const SearchedRun a = run_contour("single", "--start-at N190 --covered 25");
  const SearchedRun b = run_contour("threaded", "--start-at N190 --covered 25 --prep-thread");
  ASSERT_EQ(a.result.exit_code, 0) << a.result.output;
  EXPECT_EQ(a.events, b.events);
}

}  // namespace
}  // namespace nck::app
