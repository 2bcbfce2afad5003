#pragma once
// Shared by the tool radius compensation tests (trc_*_test.cpp): one run of
// `nck run` with events, an every-cycle trace and the final state, and
// lookups of where the tool stood when a block started.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>

#include "cli_helpers.hpp"

namespace nck::app::trc_testing {

using namespace nck::app::testing;
using nlohmann::json;

// F600 = 10 mm/s: a block's last cycle is at most 0.01 mm from its end.
inline constexpr double kTol = 0.011;

struct TrcRun {
  CliResult cli;
  std::filesystem::path dir;
  std::vector<std::string> cols;             // trace header
  std::vector<std::vector<double>> rows;     // trace, every cycle
  std::map<long, double> block_t;            // N -> start time
  std::vector<json> errors;
  std::vector<json> trc_events;
  std::vector<json> events;                  // all of them, in order
  json final_state;
};

inline TrcRun run(const std::string& machine, const std::filesystem::path& program, const std::filesystem::path& dir) {
  TrcRun r;
  r.dir = dir;
  // machine: an example's name, or the path of a machine folder
  const std::string folder = machine.find('/') == std::string::npos ? root() + "/examples/" + machine : machine;
  r.cli = run_nck("run " + folder + " " + program.string() + " --events " +
                  (dir / "e.jsonl").string() + " --trace " + (dir / "t.csv").string() + " --final " +
                  (dir / "f.json").string());
  const auto lines = split(read_file(dir / "t.csv"), '\n');
  if (!lines.empty()) r.cols = split(lines[0], ',');
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    std::vector<double> row;
    for (const std::string& c : split(lines[i], ',')) row.push_back(std::stod(c));
    r.rows.push_back(row);
  }
  for (const json& e : read_jsonl(dir / "e.jsonl")) {
    if (e["ev"] == "block" && !e["n"].is_null()) r.block_t[e["n"].get<long>()] = e["t"];
    if (e["ev"] == "error") r.errors.push_back(e);
    if (e["ev"] == "trc") r.trc_events.push_back(e);
    r.events.push_back(e);
  }
  if (std::filesystem::exists(dir / "f.json")) r.final_state = json::parse(read_file(dir / "f.json"));
  return r;
}

inline TrcRun run_text(const std::string& machine, const std::string& name, const std::string& program) {
  const auto dir = temp_dir(name);
  std::ofstream(dir / "p.nc") << program;
  return run(machine, dir / "p.nc", dir);
}

inline std::size_t col(const TrcRun& r, const std::string& name) {
  for (std::size_t i = 0; i < r.cols.size(); ++i)
    if (r.cols[i] == name) return i;
  ADD_FAILURE() << "no trace column " << name;
  return 0;
}

// The row of the last cycle before block n starts: where everything before it ended.
inline const std::vector<double>& before_block(const TrcRun& r, long n) {
  const double t = r.block_t.at(n);
  std::size_t i = 0;
  while (i + 1 < r.rows.size() && r.rows[i + 1][0] < t - 1e-9) ++i;
  return r.rows[i];
}

struct Point {
  long n;       // block
  double a, b;  // where the tool centre is when it starts
};

inline void expect_points(const TrcRun& r, const std::string& a, const std::string& b, const std::vector<Point>& pts) {
  const std::size_t ca = col(r, a), cb = col(r, b);
  for (const Point& p : pts) {
    ASSERT_TRUE(r.block_t.count(p.n)) << "no block event N" << p.n;
    const auto& row = before_block(r, p.n);
    EXPECT_NEAR(row[ca], p.a, kTol) << a << " before N" << p.n;
    EXPECT_NEAR(row[cb], p.b, kTol) << b << " before N" << p.n;
  }
}

// Trace rows in [start of n0, start of n1).
inline std::vector<std::vector<double>> between(const TrcRun& r, long n0, long n1) {
  std::vector<std::vector<double>> out;
  for (const auto& row : r.rows)
    if (row[0] >= r.block_t.at(n0) - 1e-9 && row[0] < r.block_t.at(n1) - 1e-9) out.push_back(row);
  return out;
}

}  // namespace nck::app::trc_testing
