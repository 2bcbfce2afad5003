#pragma once
// The machine's state as its inputs made it (E-stop, machine on) changed:
// one `machine` event on channel 0 with all of it, so that a reader of the
// events file needs no earlier event to know where the machine stands.
// The state a machine starts in (on, no E-stop, drives enabled) gives none,
// so runs that never touch these inputs write exactly what they wrote before.
#include "nck/core/event_head.hpp"

namespace nck::kernel::ev {

// Also what TickOutput::machine gives every cycle (kernel::MachineOutput).
struct Machine {
  bool estop = false;           // the E-stop input is on
  bool reset_needed = false;    // a channel keeps the E-stop latched until its reset
  bool machine_on = true;       // the machine-on input
  bool drives_enabled = true;   // the NC lets the drives be powered (false: E-stop or off, at standstill)
  bool operator==(const Machine&) const = default;
};

template <class Json, class Names>
void write_json(Json& j, const Machine& e, const EventHead&, const Names&) {
  j["estop"] = e.estop;
  j["reset_needed"] = e.reset_needed;
  j["machine_on"] = e.machine_on;
  j["drives_enabled"] = e.drives_enabled;
}

}  // namespace nck::kernel::ev
