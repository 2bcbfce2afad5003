#pragma once
// Parsing a scenario text in a test: the scenario with its diagnostics, the
// one action of a good line, the one diagnostic of a bad line.
#include <string_view>
#include <variant>

#include <gtest/gtest.h>

#include "nck/sim/scenario.hpp"

namespace nck::sim::testing {

struct Parsed {
  Scenario sc;
  Diagnostics diags;
};

inline Parsed parse(std::string_view text) {
  Parsed p;
  p.sc = parse_scenario(text, "s.plc", p.diags);
  return p;
}

// The one action a single-line scenario gives, with no diagnostics.
inline ScenarioAction one(std::string_view line) {
  auto p = parse(line);
  EXPECT_TRUE(p.diags.empty()) << line << ": " << (p.diags.empty() ? "" : format(p.diags.items()[0]));
  EXPECT_EQ(p.sc.actions.size(), 1u) << line;
  return p.sc.actions.empty() ? ScenarioAction{} : p.sc.actions[0];
}

// The single diagnostic a single-line scenario gives.
inline Diagnostic bad(std::string_view text) {
  auto p = parse(text);
  EXPECT_EQ(p.diags.items().size(), 1u) << text;
  EXPECT_TRUE(p.sc.actions.empty()) << text;
  return p.diags.items().empty() ? Diagnostic{} : p.diags.items()[0];
}

// The fields tests read across kinds: the switch, the percentage, the
// spindle named and the spindle command (defaults where the kind has none).
inline bool on_of(const ScenarioAction& a) {
  return std::visit([](const auto& p) {
    if constexpr (requires { p.on; }) return p.on;
    else if constexpr (requires { p.manual; }) return p.manual;
    else return false;
  }, a.payload);
}
inline double percent_of(const ScenarioAction& a) {
  return std::visit([](const auto& p) {
    if constexpr (requires { p.percent; }) return p.percent;
    else return -1.0;
  }, a.payload);
}
inline act::SpindleRef spindle_of(const ScenarioAction& a) {
  return std::visit([](const auto& p) {
    if constexpr (requires { p.spindle; }) return p.spindle;
    else return act::SpindleRef{};
  }, a.payload);
}
inline plc::ExtSpindleCommand cmd_of(const ScenarioAction& a) {
  const auto* c = a.get<act::SpindleCmd>();
  EXPECT_TRUE(c);
  return c ? c->cmd : plc::ExtSpindleCommand{};
}
template <class T>
T payload(const ScenarioAction& a) {
  const T* p = a.get<T>();
  EXPECT_TRUE(p) << action_name(a.kind());
  return p ? *p : T{};
}

}  // namespace nck::sim::testing
