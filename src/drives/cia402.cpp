#include "nck/drives/cia402.hpp"

namespace nck::drives::cia402 {
namespace {

// The profile's state masks: which statusword bits tell a state, and their values.
struct Pattern {
  std::uint16_t mask, value;
  State state;
};
constexpr Pattern kPatterns[] = {
    {0x004F, 0x0000, State::not_ready_to_switch_on},
    {0x004F, 0x0040, State::switch_on_disabled},
    {0x006F, 0x0021, State::ready_to_switch_on},
    {0x006F, 0x0023, State::switched_on},
    {0x006F, 0x0027, State::operation_enabled},
    {0x006F, 0x0007, State::quick_stop_active},
    {0x004F, 0x000F, State::fault_reaction_active},
    {0x004F, 0x0008, State::fault},
};

// What a controlword asks for, by the profile's command table (fault
// reset is the caller's: it needs the previous word).
enum class Command : std::uint8_t { disable_voltage, quick_stop, shutdown, switch_on, enable_operation };

Command command_of(std::uint16_t c) noexcept {
  if (!(c & cw::enable_voltage_bit)) return Command::disable_voltage;
  if (!(c & cw::quick_stop_bit)) return Command::quick_stop;
  if (!(c & cw::switch_on_bit)) return Command::shutdown;
  return (c & cw::enable_operation_bit) ? Command::enable_operation : Command::switch_on;
}

// The transitions the profile numbers 2 to 12 and 16, from state s under command c.
State next(State s, Command c) noexcept {
  switch (s) {
    case State::switch_on_disabled:
      return c == Command::shutdown ? State::ready_to_switch_on : s;  // 2
    case State::ready_to_switch_on:
      if (c == Command::disable_voltage || c == Command::quick_stop) return State::switch_on_disabled;  // 7
      if (c == Command::switch_on) return State::switched_on;                                              // 3
      if (c == Command::enable_operation) return State::operation_enabled;                                 // 3 + 4
      return s;
    case State::switched_on:
      if (c == Command::disable_voltage || c == Command::quick_stop) return State::switch_on_disabled;  // 10
      if (c == Command::shutdown) return State::ready_to_switch_on;                                        // 6
      if (c == Command::enable_operation) return State::operation_enabled;                                 // 4
      return s;
    case State::operation_enabled:
      if (c == Command::disable_voltage) return State::switch_on_disabled;  // 9
      if (c == Command::quick_stop) return State::quick_stop_active;        // 11
      if (c == Command::shutdown) return State::ready_to_switch_on;         // 8
      if (c == Command::switch_on) return State::switched_on;               // 5
      return s;
    case State::quick_stop_active:
      if (c == Command::disable_voltage) return State::switch_on_disabled;  // 12
      if (c == Command::enable_operation) return State::operation_enabled;  // 16
      return s;
    default:
      return s;
  }
}

}  // namespace

std::string_view name(State s) noexcept {
  constexpr std::string_view kNames[] = {"not ready to switch on", "switch on disabled", "ready to switch on",
                                         "switched on", "operation enabled", "quick stop active",
                                         "fault reaction active", "fault"};
  return kNames[static_cast<std::size_t>(s)];
}

State decode(std::uint16_t statusword) noexcept {
  for (const Pattern& p : kPatterns)
    if ((statusword & p.mask) == p.value) return p.state;
  return State::not_ready_to_switch_on;  // no pattern: the drive is not up
}

std::uint16_t statusword_bits(State s) noexcept {
  for (const Pattern& p : kPatterns)
    if (p.state == s) {
      // Voltage is on from "ready to switch on" to a quick stop.
      const bool powered = s == State::ready_to_switch_on || s == State::switched_on ||
                           s == State::operation_enabled || s == State::quick_stop_active;
      return static_cast<std::uint16_t>(p.value | sw::remote | (powered ? sw::voltage_enabled : 0));
    }
  return sw::remote;
}

std::uint16_t Master::controlword(State now, Goal goal) noexcept {
  if (goal != goal_) {
    goal_ = goal;
    waiting_ = 0;
  }
  const bool reached = (goal == Goal::enabled && now == State::operation_enabled) ||
                       (goal == Goal::disabled && (now == State::switch_on_disabled || now == State::fault)) ||
                       (goal == Goal::quick_stop && (now == State::quick_stop_active || now == State::switch_on_disabled));
  waiting_ = reached ? 0 : waiting_ + 1;
  std::uint16_t out = cw::disable_voltage;
  switch (now) {
    case State::fault:
      // Reset only to power up again; the edge needs bit 7 low first.
      out = goal == Goal::enabled && !(last_ & cw::fault_reset_bit) ? cw::fault_reset : cw::disable_voltage;
      break;
    case State::switch_on_disabled:
      out = goal == Goal::enabled ? cw::shutdown : cw::disable_voltage;
      break;
    case State::ready_to_switch_on:
      out = goal == Goal::enabled ? cw::switch_on : cw::disable_voltage;
      break;
    case State::switched_on:
    case State::operation_enabled:
      out = goal == Goal::enabled ? cw::enable_operation
            : goal == Goal::quick_stop ? cw::quick_stop
                                       : cw::disable_voltage;
      break;
    case State::quick_stop_active:
      out = goal == Goal::enabled ? cw::enable_operation : goal == Goal::quick_stop ? cw::quick_stop : cw::disable_voltage;
      break;
    case State::not_ready_to_switch_on:
    case State::fault_reaction_active:
      out = cw::disable_voltage;  // the drive moves on by itself
      break;
  }
  last_ = out;
  return out;
}

std::uint16_t Device::step(std::uint16_t controlword, bool fault) noexcept {
  const bool reset_edge = (controlword & cw::fault_reset_bit) && !(last_controlword_ & cw::fault_reset_bit);
  last_controlword_ = controlword;
  if (fault && state_ != State::fault && state_ != State::fault_reaction_active) {  // 13
    state_ = State::fault_reaction_active;
    reaction_left_ = reaction_cycles_;
  } else if (state_ == State::fault_reaction_active) {
    if (reaction_left_ == 0 || --reaction_left_ == 0) state_ = State::fault;  // 14
  } else if (state_ == State::fault) {
    if (reset_edge && !fault) state_ = State::switch_on_disabled;  // 15
  } else if (state_ == State::not_ready_to_switch_on) {
    state_ = State::switch_on_disabled;  // 1: the drive's own start-up
  } else {
    state_ = next(state_, command_of(controlword));
  }
  return statusword_bits(state_);
}

}  // namespace nck::drives::cia402
