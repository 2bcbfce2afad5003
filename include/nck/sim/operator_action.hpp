#pragma once
// An operator's action on a running kernel (nck serve, the Python session):
// one line of the --plc scenario grammar without its time —
// "feed_override 80", "ch=2 feedhold on", "jog X + 600", "mdi G0 X10" — read
// by the very parser and checked by the very resolver as a scenario file,
// so a key pressed in the browser, a Python call and a scenario line mean
// the same thing (docs/plc-scenario.md is the grammar of all three).
#include <optional>
#include <string>
#include <string_view>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/sim/scenario.hpp"

namespace nck::sim {

struct OperatorAction {
  ScenarioAction action;  // for the simulated machine's next cycle (MachineSim::operate)
  std::string mdi_text;   // action.kind == mdi: the NC block, for preparation
};

// setup side: the action of `line`, or nothing with the reason in diags
// (`source` names where the line came from in the diagnostic). block_search
// and triggered '@state' lines are refused: they belong to a run's start and
// to a scenario file.
std::optional<OperatorAction> parse_operator_action(std::string_view line, const config::Machine& m,
                                                    Diagnostics& diags, const std::string& source = "operator");

}  // namespace nck::sim
