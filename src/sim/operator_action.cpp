#include "nck/sim/operator_action.hpp"

#include <fmt/format.h>

#include "nck/plc/hli.hpp"
#include "scenario_text.hpp"

namespace nck::sim {

std::optional<OperatorAction> parse_operator_action(std::string_view line, const config::Machine& m,
                                                    Diagnostics& diags, const std::string& source) {
  const SourceLoc loc{source, 1, 0};
  if (line.find('\n') != std::string_view::npos || line.find('\r') != std::string_view::npos) {
    diags.add(ErrorId::PlcOperatorActionBad, loc, "an operator action is one line");
    return std::nullopt;
  }
  // Time 0 in front: the scenario parser then reads the line as written.
  Diagnostics found;
  Scenario sc = parse_scenario(fmt::format("0 {}", line), source, found);
  resolve_spindles(sc, m, plc::build_spindle_map(m), found);
  if (found.has_errors()) {
    for (const Diagnostic& d : found.items())
      diags.add(ErrorId::PlcOperatorActionBad, loc, fmt::format("'{}': {} ({})", detail::printable(line),
                                                                d.message, number(d.id)));
    return std::nullopt;
  }
  if (sc.actions.size() != 1) {
    diags.add(ErrorId::PlcOperatorActionBad, loc, fmt::format("'{}' is no action", detail::printable(line)));
    return std::nullopt;
  }
  OperatorAction op{sc.actions.front(), {}};
  if (op.action.kind == ActionKind::block_search) {
    diags.add(ErrorId::PlcOperatorActionNotLive, loc, "block_search starts a run: it is no action on a running kernel");
    return std::nullopt;
  }
  if (op.action.kind == ActionKind::mdi) op.mdi_text = sc.texts.front();
  return op;
}

}  // namespace nck::sim
