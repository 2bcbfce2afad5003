#pragma once
// The --plc FILE scenario: timed HLI writes, one per line (grammar in
// docs/plc-scenario.md). Parsed at setup into a time-sorted list; replayed in
// the cyclic path by the simulated machine (nck/sim/scenario_player.hpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/kernel/program_state.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/plc/ext_command.hpp"
#include "nck/plc/hli.hpp"
#include "nck/prep/search_mark.hpp"
#include "nck/sim/scenario_action.hpp"

namespace nck::sim {

struct Scenario {
  std::string file;
  std::vector<ScenarioAction> actions;  // sorted by time, file order within equal times
  std::vector<std::string> texts;       // MDI lines' text (act::Mdi::text is the index)
  std::vector<ScenarioAction> triggered;  // lines that wait for a program state ('@hold'), in file order
};

inline constexpr std::size_t kMaxScenarioActions = 100000;
inline constexpr double kMaxOverridePercent = 200.0;

// setup: parses the text of a scenario file. Bad lines are skipped and
// reported in diags (ID, file, line, column); never throws on any input.
Scenario parse_scenario(std::string_view text, std::string file, Diagnostics& diags);

// The scenario's block_search line as a block search of its channel (0-based), if it has one.
struct ScenarioSearch {
  std::size_t channel = 0;
  prep::SearchMark mark;
};
std::optional<ScenarioSearch> block_search_of(const Scenario& sc);

// setup: checks the action's channel, spindle and axis names against the
// machine and fills in their indices (act::SpindleRef, act::AxisRef and
// cmd.spindle). "S" names the channel's main spindle as configured
// (main_spindle_ax_nr). false (and the reason in diags, at `file` and the
// action's line) when the action cannot act on this machine.
bool resolve_action(ScenarioAction& a, const config::Machine& m, const plc::SpindleMap& map,
                    const std::string& file, Diagnostics& diags);

// setup: resolve_action for every line; unresolvable ones are reported and removed.
void resolve_spindles(Scenario& sc, const config::Machine& m, const plc::SpindleMap& map,
                      Diagnostics& diags);

}  // namespace nck::sim
