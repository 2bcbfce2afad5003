// G74 on a real drive in a channel: the homing block's motion waits while
// its axes search their cam or their CiA 402 drives home (HomingSearch,
// units/homing_search.hpp); the search moves the path's set point itself,
// and the block's motion then starts where the axes stand, in the
// coordinates homing set (docs/decisions.md "Homing on a real drive").
#include "channel.hpp"

namespace nck::kernel {

void Channel::begin_homing_search(const HomeAxes* home, Cycle& cy) noexcept {
  if (!home) return;
  search_.begin(home->mask);
  if (search_.active()) cy.emit(ev::Wait{WaitReason::homing, std::nullopt});
}

void Channel::step_homing_search(Cycle& cy) noexcept {
  const bool was_active = search_.active();
  if (resetting_) search_.abort();  // a reset, an E-stop or a drive's error: brake, no reference
  const motion::AxisVector machine = machine_position();
  std::array<HomingAxisInput, kMaxAxes> in{};
  for (std::size_t j = 0; j < n_axes_ && j < kMaxAxes; ++j) {
    in[j].machine_pos_mm = machine[j];
    const std::int8_t a = machine_axis_[j];
    if (a < 0) continue;
    const auto i = static_cast<std::size_t>(a);
    if (cy.machine.axes) in[j].cam = (*cy.machine.axes)[i].home_cam;
    in[j].drive_homed = (cy.machine.drives.homed >> i & 1u) != 0;
    if (cy.machine.drive_feedback) in[j].drive_pos_mm = (*cy.machine.drive_feedback)[i].actual_pos;
  }
  AxisArray shift_mm{};
  const bool hold = cy.in.feedhold || cy.stopped;
  const ErrorId error = search_.step(in, hold, cy.dt_s, shift_mm);
  motion::AxisVector& pos = path_.position();
  for (std::size_t j = 0; j < n_axes_ && j < kMaxAxes; ++j) pos[j] += shift_mm[j];
  if (error != ErrorId{}) {
    raise(error, std::nullopt, cy, machine_axis_[static_cast<std::size_t>(search_.failed_axis())]);
    return;
  }
  if (!was_active || search_.active() || !active_) return;
  cy.emit(ev::WaitEnd{ev::Wait{WaitReason::homing, std::nullopt}});
  // The homing block's motion runs from where the axes stand now.
  if (const Motion* m = current_.as<Motion>()) path_.rejoin(*m);
}

}  // namespace nck::kernel
