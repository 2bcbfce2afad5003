#pragma once
// The API's command messages (POST /api/v1/command, docs/api.md): one JSON
// object whose "command" picks the schema; every field is checked for its
// name, type and range before anything acts. An operator command becomes
// the typed action a --plc scenario line builds (sim::ScenarioAction), its
// names resolved later by the same code as a scenario file's
// (sim::check_operator_action): the server, the Python session and
// scenario files share one action and one set of checks.
//
// Plain data and no std::expected: the libFuzzer target compiles this file
// with clang 14.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "nck/core/diagnostic.hpp"
#include "nck/sim/scenario_action.hpp"

namespace nck::app::serve {

struct ApiCommand {
  enum class Kind : std::uint8_t {
    action,       // an operator action: `action` (typed; spindle and axis names not yet resolved)
    action_line,  // a scenario line without time the user typed ("action"): `line`, the channel in front
    mdi,         // NC text for the channel (`text`)
    load,        // a program for the channel (`program`, optional `start_at`)
    pause,       // the kernel's cycles stop (`on`) or go on
    step_cycle,  // one cycle while paused
    speed,       // simulated seconds per wall second (`speed`, 0 = as fast as possible)
  };
  Kind kind = Kind::action;
  std::uint8_t channel = 1;  // 1-based
  sim::ScenarioAction action;
  std::string line;
  std::string text;
  std::string program;
  std::string start_at;  // block-search mark, as nck run --start-at takes it
  bool on = false;
  // mdi: queue the text behind one that runs (TF5200 "extended manual block
  // mode", ADD_MDI_BLOCK); without it such a text is refused (930710).
  bool queue = false;
  double speed = 1;
};

inline constexpr std::size_t kMaxCommandBytes = 64 * 1024;
inline constexpr std::size_t kMaxMdiChars = 4000;  // one NC block (docs/nc-language.md)

// The command in `body`, or nothing and the reason (ID, "api" as the file).
std::optional<ApiCommand> parse_api_command(std::string_view body, std::size_t channels, Diagnostics& diags);

}  // namespace nck::app::serve
