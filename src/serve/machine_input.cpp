// POST /api/v1/estop and /api/v1/machine_on ({"on": bool}, token
// required like every request): the machine's E-stop and machine-on
// inputs, passed to the kernel as the PLC's inputs are. While the E-stop
// is on, or has not been reset since its release, or the machine is off,
// cycle start, MDI and jog are refused here with the kernel's ID (409), so
// that no new run is staged either. Not a safety function: a machine's
// E-stop chain is hardware (docs/api.md).
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "nck/serve/serve_api.hpp"
#include "nck/sim/scenario_action.hpp"

namespace nck::app::serve {

HttpReply ServeApi::machine_input(std::string_view path, std::string_view body) {
  const nlohmann::json j = nlohmann::json::parse(body, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return error_reply(400, ErrorId::ApiMalformedJson, "the body is not one JSON object");
  for (const auto& [key, value] : j.items())
    if (key != "on") return error_reply(400, ErrorId::ApiUnknownField, fmt::format("'{}' is no field of {}", key.substr(0, 40), path));
  const auto on = j.find("on");
  if (on == j.end() || !on->is_boolean()) return error_reply(400, ErrorId::ApiBadValue, fmt::format("{} needs 'on' (true or false)", path));
  const bool is_estop = path == "/api/v1/estop";
  const sim::ScenarioAction a = is_estop ? sim::make_action(1, sim::act::Estop{on->get<bool>()})
                                         : sim::make_action(1, sim::act::MachineOn{on->get<bool>()});
  if (!kernel_.operate(a)) return error_reply(429, ErrorId::PlcOperatorActionsFull, "the kernel has 64 actions waiting");
  note_machine_input(a);
  return HttpReply{200, "application/json",
                   nlohmann::json{{"ok", true}, {"estop", estop_}, {"machine_on", machine_on_}}.dump(), {}};
}

// Whatever way the input came (this route, or a command's `action` line
// "estop on"), the server keeps it: a new run (a fresh kernel) is never
// started while it refuses.
void ServeApi::note_machine_input(const sim::ScenarioAction& a) {
  if (const auto* e = a.get<sim::act::Estop>()) {
    estop_ = e->on;
    if (e->on) reset_pending_.fill(true);
  } else if (const auto* m = a.get<sim::act::MachineOn>()) {
    machine_on_ = m->on;
  } else if (a.kind() == sim::ActionKind::reset && !estop_ && a.channel >= 1 && a.channel <= reset_pending_.size()) {
    reset_pending_[a.channel - 1u] = false;  // that channel's latch in the kernel goes with it
  }
}

std::optional<HttpReply> ServeApi::refused_by_machine(sim::ActionKind kind, std::size_t ch) const {
  using K = sim::ActionKind;
  if (kind != K::cycle_start && kind != K::mdi && kind != K::jog && kind != K::jog_increment) return std::nullopt;
  // The kernel latches the E-stop as this server does (no other source
  // gives it here); the server's own flags answer at once, with no wait
  // for the next snapshot.
  const bool pending = ch < reset_pending_.size() && reset_pending_[ch];
  if (estop_ || pending)
    return error_reply(409, ErrorId::KernelEstopRefused,
                       estop_ ? "the E-stop is active: release it, then reset the channel"
                              : "the E-stop was released but not reset: reset the channel first");
  if (!machine_on_) return error_reply(409, ErrorId::KernelMachineOffRefused, "the machine is off: switch it on first");
  return std::nullopt;
}

}  // namespace nck::app::serve
