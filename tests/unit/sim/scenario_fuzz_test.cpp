// Garbage in, diagnostics out: random bytes and mutated valid scenarios must
// never crash, hang or throw, and every kept action must be well-formed.
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "scenario_parse_helpers.hpp"

#include "nck/sim/scenario.hpp"
#include "nck/sim/machine_sim.hpp"

namespace nck::sim {
namespace {

constexpr std::string_view kValid =
    "# scenario\n"
    "0.5 override S1 50\n"
    "1.0 feed_override 80\n"
    "1.2 feedhold on\n"
    "2.0 spindle_stop_at_end on\n"
    "2.5 reset\n"
    "3.0 spindle_cmd S2 M3 REV500\n"
    "3.1 ch=2 spindle_cmd S3 M19 REV=100 POS=45\n"
    "3.2 channel 2 silent on\n"
    "4 optional_stop off # trailing\n";

// Case count from the environment (NCK_FUZZ_CASES), like ruckig's property tests.
int cases(int fallback) {
  const char* env = std::getenv("NCK_FUZZ_CASES");
  return env != nullptr ? std::max(1, std::atoi(env)) : fallback;
}

void check_invariants(const Scenario& sc, const Diagnostics& d) {
  double prev = 0;
  for (const auto& a : sc.actions) {
    ASSERT_TRUE(std::isfinite(a.t_s));
    ASSERT_GE(a.t_s, prev);
    prev = a.t_s;
    ASSERT_GE(a.channel, 1);
    ASSERT_LE(a.channel, config::kMaxChannels);
    ASSERT_GE(a.line, 1u);
    ASSERT_EQ(testing::spindle_of(a).name.back(), '\0');
    if (std::visit([](const auto& p) { return requires { p.percent; }; }, a.payload)) {
      ASSERT_GE(testing::percent_of(a), 0);
      ASSERT_LE(testing::percent_of(a), kMaxOverridePercent);
    }
  }
  for (const auto& di : d.items()) {
    ASSERT_GE(number(di.id), 960000u);
    ASSERT_LT(number(di.id), 970000u);
    ASSERT_GE(di.loc.line, 1u);
    ASSERT_FALSE(di.message.empty());
  }
}

void run(std::string_view text) {
  Diagnostics d;
  Scenario sc = parse_scenario(text, "fuzz.plc", d);
  check_invariants(sc, d);
  // Replay too: resolve against a one-channel machine and apply everything.
  config::Machine m;
  m.channels.resize(1);
  m.channels[0].spindles.resize(1);
  m.channels[0].spindles[0].name = "S1";
  m.channels[0].spindles[0].log_axis_nr = 1;
  auto map = plc::build_spindle_map(m);
  resolve_spindles(sc, m, map, d);
  sim::MachineSim machine(m);
  machine.load_scenario(sc);
  auto in = std::make_unique<kernel::TickInput>();
  machine.read(std::numeric_limits<double>::infinity(), *in);
  // Every spindle command arrives or is counted as lost.
  std::size_t commands = 0;
  for (const auto& a : sc.actions) commands += a.kind() == ActionKind::spindle_cmd && testing::spindle_of(a).index >= 0;
  ASSERT_EQ(in->ext_commands.size() + in->ext_commands_lost, commands);
}

TEST(ScenarioFuzz, ValidSampleParsesClean) {
  Diagnostics d;
  auto sc = parse_scenario(kValid, "v.plc", d);
  EXPECT_TRUE(d.empty());
  EXPECT_EQ(sc.actions.size(), 9u);
}

TEST(ScenarioFuzz, RandomBytes) {
  std::mt19937 rng(20240601);
  const int n = cases(2000);
  for (int i = 0; i < n; ++i) {
    std::uniform_int_distribution<int> len(0, 300), byte(0, 255);
    std::string s(static_cast<std::size_t>(len(rng)), '\0');
    for (auto& c : s) c = static_cast<char>(byte(rng));
    SCOPED_TRACE(i);
    run(s);
  }
}

TEST(ScenarioFuzz, MutatedValidScenario) {
  std::mt19937 rng(42);
  const std::string alphabet = " \t\n#.=-+eE0123456789SMREVPOSonfch_\r\x00\xff";
  const int n = cases(3000);
  for (int i = 0; i < n; ++i) {
    std::string s(kValid);
    std::uniform_int_distribution<int> edits(1, 12);
    for (int e = edits(rng); e > 0; --e) {
      std::uniform_int_distribution<std::size_t> pos(0, s.size());
      std::uniform_int_distribution<int> op(0, 3);
      std::uniform_int_distribution<std::size_t> ch(0, alphabet.size() - 1);
      const std::size_t at = pos(rng);
      switch (op(rng)) {
        case 0: s.insert(at, 1, alphabet[ch(rng)]); break;            // insert
        case 1: if (at < s.size()) s.erase(at, 1); break;            // delete
        case 2: if (at < s.size()) s[at] = alphabet[ch(rng)]; break; // replace
        default: s.insert(at, s.substr(at, 20)); break;              // duplicate a run
      }
    }
    SCOPED_TRACE(s);
    run(s);
  }
}

TEST(ScenarioFuzz, HugeNumbersAndLongLines) {
  run("1e308 reset\n1e309 reset\n0 feed_override 1e400\n");
  run(std::string(100000, 'x'));
  run("0 spindle_cmd S1 M3 REV" + std::string(5000, '9') + "\n");
  run(std::string(5000, '\n') + "1 reset");
}

}  // namespace
}  // namespace nck::sim
