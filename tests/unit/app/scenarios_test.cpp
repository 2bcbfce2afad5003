// Data-driven scenario tests: every folder under tests/scenarios/ holds a
// scenario.json (format: tests/scenarios/README.md); each becomes one test
// that runs `nck run` and checks exit code, events in order, final state
// and trace values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path scenarios_dir() { return fs::path(root()) / "tests" / "scenarios"; }

// The scenario folders, read when the test program starts (gtest discovery
// runs the program, so ctest sees one entry per folder).
std::vector<std::string> scenario_names() {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(scenarios_dir(), ec))
    if (e.is_directory() && fs::exists(e.path() / "scenario.json")) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// "examples/..." is relative to the repository, anything else to the scenario folder.
fs::path resolve(const fs::path& scenario, const std::string& p) {
  return p.rfind("examples/", 0) == 0 ? fs::path(root()) / p : scenario / p;
}

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// `want` matches `got`: numbers within tol, objects by the keys `want`
// names (others are ignored), arrays element by element, the rest exactly.
bool matches(const json& want, const json& got, double tol) {
  if (want.is_number()) return got.is_number() && std::abs(want.get<double>() - got.get<double>()) <= tol;
  if (want.is_object()) {
    if (!got.is_object()) return false;
    for (const auto& [k, v] : want.items())
      if (!got.contains(k) || !matches(v, got[k], tol)) return false;
    return true;
  }
  if (want.is_array()) {
    if (!got.is_array() || got.size() != want.size()) return false;
    for (std::size_t i = 0; i < want.size(); ++i)
      if (!matches(want[i], got[i], tol)) return false;
    return true;
  }
  return want == got;
}

// One expected event: its fields, and the optional t_min / t_max / tol.
bool event_matches(const json& want, const json& ev) {
  const double tol = want.value("tol", 1e-6);
  const double t = ev.value("t", 0.0);
  if (want.contains("t_min") && t < want["t_min"].get<double>() - 1e-9) return false;
  if (want.contains("t_max") && t > want["t_max"].get<double>() + 1e-9) return false;
  json fields = want;
  for (const char* k : {"t_min", "t_max", "tol"}) fields.erase(k);
  return matches(fields, ev, tol);
}

void check_events(const json& expected, const std::vector<json>& events) {
  std::size_t from = 0;
  for (const json& want : expected) {
    auto it = std::find_if(events.begin() + static_cast<long>(from), events.end(),
                           [&](const json& e) { return event_matches(want, e); });
    if (it == events.end()) {
      std::string seen;
      for (std::size_t i = from; i < events.size() && i < from + 40; ++i)
        if (events[i]["ev"] != "block") seen += "  " + events[i].dump() + "\n";
      ADD_FAILURE() << "event not found (in order): " << want.dump() << "\nnon-block events after the previous match:\n"
                    << seen;
      return;
    }
    from = static_cast<std::size_t>(it - events.begin()) + 1;
  }
}

void check_forbidden(const json& forbidden, const std::vector<json>& events) {
  for (const json& want : forbidden)
    for (const json& e : events)
      EXPECT_FALSE(event_matches(want, e)) << "forbidden event " << e.dump();
}

void check_final(const json& checks, const json& final_state) {
  for (const json& c : checks) {
    const json::json_pointer ptr(c.at("path").get<std::string>());
    if (!final_state.contains(ptr)) {
      ADD_FAILURE() << "final state has no " << ptr.to_string();
      continue;
    }
    EXPECT_TRUE(matches(c.at("value"), final_state[ptr], c.value("tol", 1e-6)))
        << ptr.to_string() << ": expected " << c["value"].dump() << ", got " << final_state[ptr].dump();
  }
}

// The value of `column` in the last trace row with t <= the asked time.
void check_trace(const json& checks, const fs::path& csv) {
  const auto lines = split(read_file(csv), '\n');
  ASSERT_FALSE(lines.empty());
  const auto header = split(lines[0], ',');
  for (const json& c : checks) {
    const std::string col = c.at("column").get<std::string>();
    const double t = c.at("t").get<double>();
    const auto ci = std::find(header.begin(), header.end(), col);
    if (ci == header.end()) {
      ADD_FAILURE() << "trace has no column " << col << " (" << lines[0] << ")";
      continue;
    }
    const auto idx = static_cast<std::size_t>(ci - header.begin());
    std::optional<double> value;
    for (std::size_t i = 1; i < lines.size(); ++i) {
      const auto cells = split(lines[i], ',');
      if (cells.size() <= idx || std::stod(cells[0]) > t + 1e-9) break;
      value = std::stod(cells[idx]);
    }
    if (!value) {
      ADD_FAILURE() << "trace has no row at t = " << t;
      continue;
    }
    EXPECT_NEAR(*value, c.at("value").get<double>(), c.value("tol", 1e-6)) << col << " at t = " << t;
  }
}

class Scenario : public ::testing::TestWithParam<std::string> {};

TEST_P(Scenario, RunsAsExpected) {
  const fs::path dir = scenarios_dir() / GetParam();
  const json s = json::parse(read_file(dir / "scenario.json"));
  static const std::set<std::string> known = {"description", "machine", "programs", "plc", "args", "exit_code",
                                              "events", "forbid_events", "final", "trace"};
  for (const auto& [k, v] : s.items()) EXPECT_TRUE(known.count(k)) << "unknown key " << k << " in scenario.json";
  ASSERT_TRUE(s.contains("events") || s.contains("final") || s.contains("trace")) << "nothing to check";

  std::string cmd = "run " + quoted(resolve(dir, s.at("machine").get<std::string>()));
  for (const json& p : s.at("programs")) cmd += " " + quoted(resolve(dir, p.get<std::string>()));
  if (s.contains("plc")) cmd += " --plc " + quoted(resolve(dir, s["plc"].get<std::string>()));
  for (const json& a : s.value("args", json::array())) cmd += " " + a.get<std::string>();
  const fs::path out = temp_dir("scenario_" + GetParam());
  cmd += " --events " + quoted(out / "e.jsonl") + " --trace " + quoted(out / "t.csv") + " --final " +
         quoted(out / "f.json");

  const CliResult r = run_nck(cmd);
  ASSERT_EQ(r.exit_code, s.value("exit_code", 0)) << r.output;
  const std::vector<json> events = read_jsonl(out / "e.jsonl");
  check_events(s.value("events", json::array()), events);
  check_forbidden(s.value("forbid_events", json::array()), events);
  if (s.contains("final")) check_final(s["final"], json::parse(read_file(out / "f.json")));
  if (s.contains("trace")) check_trace(s["trace"], out / "t.csv");
  if (!HasFailure()) fs::remove_all(out);
}

std::string param_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string n = info.param;
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Folders, Scenario, ::testing::ValuesIn(scenario_names()), param_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(Scenario);

}  // namespace
}  // namespace nck::app::testing
