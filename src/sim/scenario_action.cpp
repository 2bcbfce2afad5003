// The typed action's defaults and the operator's words the scenario grammar
// and the Python session read alike.
#include "nck/sim/scenario_action.hpp"

#include <array>
#include <utility>

#include "nck/sim/operator_action.hpp"
#include "scenario_text.hpp"

namespace nck::sim {

std::optional<std::int8_t> jog_direction_word(std::string_view word, bool stop_allowed) {
  if (word == "+") return 1;
  if (word == "-") return -1;
  if (stop_allowed && detail::iequals(word, "stop")) return 0;
  return std::nullopt;
}

std::optional<bool> manual_mode_word(std::string_view word) {
  if (detail::iequals(word, "manual")) return true;
  if (detail::iequals(word, "automatic")) return false;
  return std::nullopt;
}

ActionPayload payload_of(ActionKind k) noexcept {
  constexpr auto kDefaults = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<ActionPayload, sizeof...(I)>{ActionPayload(std::in_place_index<I>)...};
  }(std::make_index_sequence<std::variant_size_v<ActionPayload>>());
  return kDefaults[static_cast<std::size_t>(k)];
}

}  // namespace nck::sim
