// Manual mode in a channel: the cycle's jog requests, taken or refused,
// and the jogged axes' travel, which joins the manual offsets (the program
// keeps it). The jog itself is the JogUnit's (units/jog_unit.hpp).
#include "channel.hpp"

namespace nck::kernel {

// Manual mode: the cycle's jog requests, each taken or refused (930720).
void Channel::take_jogs(Cycle& cy) noexcept {
  const ErrorId refused = refusal(cy);
  for (const JogRequest& r : cy.in.jogs) {
    if (refused != ErrorId{} && r.kind != JogRequest::Kind::stop) {
      cy.emit(ev::Warning{{refused, {}, {}}});
      continue;
    }
    if (refuse_jog_into_switch(r, cy)) continue;
    if (jog_allowed(r)) {
      jog_.take(r, cy);
      continue;
    }
    cy.emit(ev::Warning{{ErrorId::KernelJogRefused, {}, {}}});
  }
}

// A jog moves an axis while the program does not (idle, hold, ended), or
// an axis in G201 manual mode at any time; a stop is always taken.
bool Channel::jog_allowed(const JogRequest& r) const noexcept {
  if (r.kind == JogRequest::Kind::stop) return true;
  if (state_ == ProgramState::idle || state_ == ProgramState::hold || state_ == ProgramState::ended) return true;
  return r.axis >= 0 && handwheel_.in_manual_mode(static_cast<std::size_t>(r.axis));
}

std::uint32_t Channel::manual_axes(const ChannelInput& in) const noexcept {
  if (!in.manual_mode) return 0;
  if (state_ != ProgramState::idle && state_ != ProgramState::hold && state_ != ProgramState::ended) return 0;
  return n_axes_ >= 32 ? ~0u : (1u << n_axes_) - 1u;
}

// The jogged axes travel on; their travel joins the manual offsets, so the
// machine set point (path + manual offset) moves and the program keeps it.
void Channel::move_jogged(Cycle& cy) noexcept {
  AxisArray position_mm{};
  AxisArray travel_mm{};
  const motion::AxisVector& pos = path_.position();
  const motion::AxisVector& manual = handwheel_.in_force_mm();
  for (std::size_t j = 0; j < n_axes_; ++j) position_mm[j] = pos[j] + manual[j];
  jog_.step(position_mm, travel_mm, cy);
  for (std::size_t j = 0; j < n_axes_; ++j)
    if (travel_mm[j] != 0) handwheel_.add_mm(j, travel_mm[j]);
}

}  // namespace nck::kernel
