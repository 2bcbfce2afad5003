#pragma once
// An operator's action on a running kernel (nck serve, the Python session):
// the typed action a scenario line builds (nck/sim/scenario_action.hpp),
// built by each surface from its own input — a JSON command, a Python call —
// and checked and resolved by the same rules as a scenario file's line, so
// a key pressed in the browser, a Python call and a scenario line mean the
// same thing (docs/plc-scenario.md is the grammar of all three).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/sim/scenario.hpp"

namespace nck::sim {

struct OperatorAction {
  ScenarioAction action;  // for the simulated machine's next cycle (MachineSim::operate)
  std::string mdi_text;   // action.kind() == mdi: the NC block, for preparation
};

// How a refusal quotes an action: as the surface's users have always seen
// it. api: numbers in their shortest form (80, 50.5); python: six
// significant digits (printf's %g), a skip mask in hex, and the spindle
// override as "override S1 50" (no channel prefix, whatever its channel).
enum class Quoting : std::uint8_t { api, python };

// setup side: the action's values checked as the scenario grammar checks a
// line's words, its names resolved against the machine (resolve_action).
// Nothing when it cannot act, and the reason in diags: the scenario
// grammar's ID, quoting the action as its scenario line (operator_line). block_search is refused: it belongs to a run's start.
std::optional<OperatorAction> check_operator_action(OperatorAction op, const config::Machine& m, Diagnostics& diags,
                                                    const std::string& source, Quoting q = Quoting::api);

// The scenario line without its time that means the same as op
// ("ch=2 jog X + 600"): how messages quote an operator's action.
std::string operator_line(const OperatorAction& op, Quoting q);

// The refusal of an operator action as check_operator_action words it:
// the scenario grammar's ID, `line` quoted before its message.
Diagnostic operator_action_refused(std::string_view line, ErrorId id, std::string_view message,
                                   const std::string& source);

// A word as refusals quote it: bytes outside printable ASCII as \xNN, at
// most 40 characters.
std::string operator_action_shown(std::string_view word);

// setup side: the action of one line of text a user typed (the API's
// "action" command, Session.action in Python), or nothing with the reason
// in diags. Triggered '@state' lines are refused: they belong to a file.
std::optional<OperatorAction> parse_operator_action(std::string_view line, const config::Machine& m,
                                                    Diagnostics& diags, const std::string& source = "operator");

// The operator's words for a jog direction (+1, -1; 0 = stop where allowed)
// and for a mode (true: manual), as the scenario grammar reads them.
std::optional<std::int8_t> jog_direction_word(std::string_view word, bool stop_allowed);
std::optional<bool> manual_mode_word(std::string_view word);

}  // namespace nck::sim
