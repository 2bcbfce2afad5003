#pragma once
// 3D distance control (#DIST CTRL) as it travels: what preparation attaches
// to the block that switches it, what the channel's DistUnit takes when the
// block starts, and the `dist_ctrl` event it reports at each change of state.
#include <array>
#include <cstdint>
#include <optional>

#include "nck/core/event_head.hpp"
#include "nck/distctrl/controller.hpp"

namespace nck::distctrl {

// #DIST CTRL: the switch and its overrides, the tool axis that carries the
// offset (the plane's third axis) and, with CHECK_SW_LIMIT_SWITCH, its
// software limits.
struct DistChange {
  enum class Source : std::uint8_t {
    machine,   // the machine's sensor (TickInput)
    variable,  // the channel variable named `variable` (TickInput's variables)
  };
  Switch sw{};
  std::int8_t axis = 0;
  std::optional<Source> source;  // none: keep the one in force
  std::array<char, 32> variable{};
  std::optional<std::array<double, 2>> sw_limits_mm;  // negative, positive
};

// The controller entered `state`.
struct StateEvent {
  State state = State::inactive;
};

template <class Json, class Names>
void write_json(Json& j, const StateEvent& e, const EventHead& h, const Names&) {
  j["state"] = state_name(e.state);
  j["line"] = h.at.line;
}

}  // namespace nck::distctrl
