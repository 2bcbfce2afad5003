#pragma once
// Reading a spindle-path run (trace every cycle, events) for the tests.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "cli_helpers.hpp"

namespace nck::app::testing {

using nlohmann::json;

inline constexpr double kDt = 0.001;  // cycle_time of the examples

// One trace row by column name.
using Row = std::map<std::string, double>;

struct PathRun {
  CliResult cli;
  std::vector<json> events;
  std::vector<Row> rows;
  // Value of column `col` in the row at time t (rows are every cycle).
  double at(double t, const std::string& col) const { return rows.at(index(t)).at(col); }
  std::size_t index(double t) const { return static_cast<std::size_t>(std::lround(t / row_dt)); }
  double row_dt = kDt;  // time between trace rows (--trace-every)
  // Time at which the block on `line` starts (-1 if never).
  double line_t(long line) const {
    for (const json& e : events)
      if (e["ev"] == "block" && e["line"] == line) return e["t"].get<double>();
    return -1;
  }
  // Time at which block `n` starts (-1 if never).
  double block_t(long n) const {
    for (const json& e : events)
      if (e["ev"] == "block" && !e["n"].is_null() && e["n"] == n) return e["t"].get<double>();
    return -1;
  }
  std::vector<json> of(const std::string& ev) const {
    std::vector<json> out;
    for (const json& e : events)
      if (e["ev"] == ev) out.push_back(e);
    return out;
  }
};

inline PathRun read_run(CliResult cli, const std::filesystem::path& dir) {
  PathRun r;
  r.cli = std::move(cli);
  r.events = read_jsonl(dir / "e.jsonl");
  const auto lines = split(read_file(dir / "t.csv"), '\n');
  if (lines.empty()) return r;
  const auto names = split(lines[0], ',');
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto cells = split(lines[i], ',');
    Row row;
    for (std::size_t c = 0; c < cells.size() && c < names.size(); ++c) row[names[c]] = std::stod(cells[c]);
    r.rows.push_back(std::move(row));
  }
  return r;
}

inline PathRun run_example_program(const std::string& machine, const std::string& program, const std::string& name) {
  const auto dir = temp_dir(name);
  CliResult c = run_example(machine, program, dir);
  return read_run(std::move(c), dir);
}

inline PathRun run_text(const std::string& machine, const std::string& text, const std::string& name,
                 const std::string& args = "") {
  const auto dir = temp_dir(name);
  std::ofstream(dir / "p.nc") << text;
  const std::string ex = machine.find('/') == std::string::npos ? root() + "/examples/" + machine : machine;
  CliResult c = run_nck("run " + ex + " " + (dir / "p.nc").string() + " --events " + (dir / "e.jsonl").string() +
                        " --trace " + (dir / "t.csv").string() + " " + args);
  return read_run(std::move(c), dir);
}

// Angle step from a to b taken the short way round (|step| < 180).
inline double wrapped_step(double a, double b) { return std::remainder(b - a, 360.0); }

// The spindle's turn (deg, unwrapped) and the travel of `axis` between rows i and j.
inline std::pair<double, double> turn_and_travel(const PathRun& r, std::size_t i, std::size_t j, const std::string& axis) {
  double turn = 0;
  for (std::size_t k = i; k < j; ++k) turn += wrapped_step(r.rows[k].at("S1.pos"), r.rows[k + 1].at("S1.pos"));
  return {turn, r.rows[j].at(axis) - r.rows[i].at(axis)};
}

// The last row before `axis` moves, searching from row `from`.
inline std::size_t before_move(const PathRun& r, std::size_t from, const std::string& axis) {
  std::size_t k = from;
  while (k + 1 < r.rows.size() && r.rows[k + 1].at(axis) == r.rows[from].at(axis)) ++k;
  return k;
}

}  // namespace nck::app::testing
