// Amplifier faults and limit switches as a channel follows them
// (TickInput::axes, by machine axis): an amplifier fault of an enabled
// axis or spindle or a limit switch that comes on brakes every axis of the channel as
// the E-stop does and ends the program in error; a move further into a
// switch that is on is refused (docs/decisions.md, "Amplifier faults and
// limit switches").
#include "channel.hpp"
#include "spindle_unit.hpp"

namespace nck::kernel {

namespace {
// Shorter than any move a block makes (mm / deg): an axis that keeps its
// position within this does not move towards its switch.
constexpr double kStillMm = 1e-9;
}  // namespace

// Reads the channel's axes' inputs: the first amplifier fault (while the
// drives are enabled: a disabled drive may well report one) and the first
// limit switch that came on this cycle each raise their error once. rt
void Channel::follow_switches(Cycle& cy) noexcept {
  if (cy.in.reset) limit_error_ = false;
  if (!cy.machine.axes) return;
  const std::array<AxisSwitches, drives::kMaxDrives>& axes = *cy.machine.axes;
  std::int8_t amp_axis = -1, hit_axis = -1;
  ErrorId hit{};
  std::uint32_t pos = 0, neg = 0;
  for (std::size_t j = 0; j < n_axes_ && j < kMaxAxes; ++j) {
    const std::int8_t a = machine_axis_[j];
    if (a < 0) continue;
    const AxisSwitches& s = axes[static_cast<std::size_t>(a)];
    const std::uint32_t bit = 1u << j;
    if (s.amp_fault && amp_axis < 0) amp_axis = a;
    if (s.pos_limit) pos |= bit;
    if (s.neg_limit) neg |= bit;
    if (hit_axis >= 0) continue;
    if ((pos & ~pos_was_ & bit) != 0) hit = ErrorId::KernelLimitSwitchPos;
    else if ((neg & ~neg_was_ & bit) != 0) hit = ErrorId::KernelLimitSwitchNeg;
    if (hit != ErrorId{}) hit_axis = a;
  }
  pos_was_ = pos;
  neg_was_ = neg;
  // A spindle's drive fails as an axis's does (its axis list's input).
  for (std::size_t i = 0; i < spindles_.size() && amp_axis < 0; ++i) {
    const SpindleUnit* u = cy.machine.spindle(spindles_[i]);
    if (u && u->axis_list >= 0 && axes[static_cast<std::size_t>(u->axis_list)].amp_fault)
      amp_axis = static_cast<std::int8_t>(u->axis_list);
  }
  if (cy.in.reset && amp_axis < 0) amp_latched_ = false;
  if (amp_axis >= 0 && !amp_latched_ && cy.machine.drives_enabled) {
    amp_latched_ = true;
    brake_for_fault(ErrorId::KernelAmpFault, amp_axis, cy);
  }
  if (hit_axis >= 0) {
    limit_error_ = true;
    brake_for_fault(hit, hit_axis, cy);
  }
}

// As the E-stop: the path brakes along its path with the emergency
// deceleration, jogs and spindles brake, the channel enters the error
// state and its program ends at standstill. rt
void Channel::brake_for_fault(ErrorId id, std::int8_t machine_axis, Cycle& cy) noexcept {
  jog_.release_all();
  halt_spindles(cy);
  set_state(ProgramState::error, StateReason::error, cy);
  ev::Error e{{id, {}, {}}};
  e.axis = machine_axis;
  cy.emit(e);
  if (!done()) {
    resetting_ = true;
    path_.brake_for_emergency(emergency_a_mm_s2_);
  }
}

// The block that just started moves an axis towards a limit switch that is
// on: it ends the program (or the MDI text) in error before anything
// moves. Judged by the block's end point: what moves away from the switch
// runs, so that the axis can leave it. rt
bool Channel::refuse_into_switch(Cycle& cy) noexcept {
  if ((pos_was_ | neg_was_) == 0 || !current_.as<Motion>()) return false;
  const motion::AxisVector& end = path_.segment().end_point();
  const motion::AxisVector& at = path_.position();
  for (std::size_t j = 0; j < n_axes_ && j < kMaxAxes; ++j) {
    const double d = end[j] - at[j];
    const int dir = d > kStillMm ? 1 : d < -kStillMm ? -1 : 0;
    if (dir == 0 || !limit_on(j, dir)) continue;
    set_state(ProgramState::error, StateReason::error, cy);
    ev::Error e{{dir > 0 ? ErrorId::KernelLimitSwitchPos : ErrorId::KernelLimitSwitchNeg, {}, {}}};
    e.axis = machine_axis_[j];
    cy.emit(e);
    end_program(EndReason::error, cy);
    return true;
  }
  return false;
}

bool Channel::refuse_jog_into_switch(const JogRequest& r, Cycle& cy) const noexcept {
  if (r.kind == JogRequest::Kind::stop || r.axis < 0) return false;
  const auto j = static_cast<std::size_t>(r.axis);
  if (j >= n_axes_ || !limit_on(j, r.direction < 0 ? -1 : 1)) return false;
  ev::Warning w{{ErrorId::KernelJogIntoLimitSwitch, {}, {}}};
  w.axis = machine_axis_[j];
  cy.emit(w);
  return true;
}

}  // namespace nck::kernel
