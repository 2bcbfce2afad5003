// The machine's inputs as a channel follows them: the E-stop and machine
// on (TickInput::machine). Neither is a safety function (a machine's E-stop
// chain is hardware); they make the NC brake and stop asking for motion
// (docs/decisions.md, "E-stop and machine on").
#include "channel.hpp"

namespace nck::kernel {

// E-stop: the program's path brakes along its path with the emergency
// deceleration (a reset's braking, with at least that deceleration), the
// spindles brake, the channel enters the error state and ends its program
// at standstill. It stays latched until a reset after the release.
// Machine off: a program that has started brakes as a reset does and ends;
// one that has not yet started waits for machine on. rt
void Channel::follow_machine(Cycle& cy) noexcept {
  const bool estop = cy.machine.estop, on = !cy.machine.machine_off;
  if (cy.in.reset && !estop) estop_latched_ = false;
  if (estop && !estop_latched_) {
    estop_latched_ = true;
    jog_.release_all();
    halt_spindles(cy);
    set_state(ProgramState::error, StateReason::error, cy);
    cy.emit(ev::Error{{ErrorId::KernelEmergencyStop, {}, {}}});
    if (!done()) {
      resetting_ = true;
      path_.brake_for_emergency(emergency_a_mm_s2_);
    }
  }
  if (!on && machine_was_on_) {
    jog_.release_all();
    halt_spindles(cy);
    if (!done() && !resetting_ && state_ != ProgramState::idle) {
      cy.emit(ev::Warning{{ErrorId::KernelMachineOff, {}, {}}});
      resetting_ = true;
    }
  }
  machine_was_on_ = on;
  follow_switches(cy);
}

// The channel's spindles brake to standstill with their ramps (a tapping
// spindle follows the path down instead: its tap is never torn). rt
void Channel::halt_spindles(Cycle& cy) noexcept {
  const ChannelContext& ctx = cy.machine;
  const std::int8_t keep = spindle_path_.tap_spindle();
  for (std::int8_t s : spindles_) {
    SpindleUnit* u = ctx.spindle(s);
    if (!u || u->channel != number_ || s == keep) continue;
    u->axis.halt();
    report_spindle_changes(*u, s, cy.t_s, cy.sink);
  }
}

ErrorId Channel::refusal(const Cycle& cy) const noexcept {
  if (estop_latched_ || cy.machine.estop) return ErrorId::KernelEstopRefused;
  if (cy.machine.machine_off) return ErrorId::KernelMachineOffRefused;
  if (amp_latched_) return ErrorId::KernelAmpFaultRefused;
  return ErrorId{};
}

// MDI typed while starts are refused is dropped with the refusal's ID
// (what else a done channel holds it drops anyway: take_mdi). rt
void Channel::refuse_mdi(ErrorId why, Cycle& cy) noexcept {
  // The rest of a text the E-stop ended goes silently (its error was said).
  while (dropping_mdi_ && !commands_->empty()) {
    dropping_mdi_ = commands_->front().mdi != Mdi::end;
    commands_->pop();
  }
  bool mdi = false;
  while (!dropping_mdi_ && !commands_->empty()) {
    mdi = mdi || commands_->front().mdi != Mdi::none;
    commands_->pop();
  }
  if (mdi) cy.emit(ev::Warning{{why, {}, {}}});
}

}  // namespace nck::kernel
