#include "jog_unit.hpp"

#include <algorithm>
#include <cmath>

#include "nck/motion/path_profile.hpp"

namespace nck::kernel {

namespace {

// An event of kind k with id at the channel's block (warnings of manual mode).
void warn(ErrorId id, Cycle& cy) noexcept {
  cy.emit(ev::Warning{{id, {}, {}}});  // the ID's table text
}

}  // namespace

void JogUnit::take(const JogRequest& r, Cycle& cy) noexcept {
  if (r.axis < 0 || static_cast<std::size_t>(r.axis) >= cy.n_axes) return warn(ErrorId::KernelJogBadRequest, cy);
  const auto j = static_cast<std::size_t>(r.axis);
  AxisJog& g = jogs_[j];
  if (r.kind == JogRequest::Kind::stop) {
    g.wanted_mm_s = 0;  // brake within a_max; a stop of an axis at rest changes nothing
    if (moving(j)) g.kind = JogRequest::Kind::stop;
    return;
  }
  const JogAxisSettings& s = settings_[j];
  const bool increment = r.kind == JogRequest::Kind::increment;
  const double asked_mm_s = r.speed_mm_s > 0 ? r.speed_mm_s : increment ? s.increment_speed_mm_s : s.speed_mm_s;
  const double speed_mm_s = std::min(asked_mm_s, s.max_speed_mm_s);
  if (!(speed_mm_s > 0) || (increment && !(r.step_mm > 0)) || r.kind == JogRequest::Kind::none)
    return warn(ErrorId::KernelJogBadRequest, cy);
  // An axis at rest starts from standstill — or from the last step's speed
  // when its jog ended in the cycle before, so that the step after it stays
  // within a_max too.
  if (!moving(j) && ((stopped_last_cycle_ >> j) & 1u) == 0) g.v_mm_s = 0;
  const std::int8_t direction = r.direction < 0 ? -1 : 1;
  // Another press in the same direction adds a step; a reversal keeps the
  // speed the axis has (now against the new direction) and brakes it first.
  const bool same_step = increment && g.kind == JogRequest::Kind::increment && g.direction == direction;
  if (g.direction != direction) g.v_mm_s = -g.v_mm_s;
  g.left_mm = same_step ? g.left_mm + r.step_mm : r.step_mm;
  g.kind = r.kind;
  g.direction = direction;
  g.wanted_mm_s = speed_mm_s;
  active_ |= 1u << j;
}

void JogUnit::step(const AxisArray& position_mm, AxisArray& travel_mm, Cycle& cy) noexcept {
  for (std::size_t j = 0; j < cy.n_axes; ++j)
    travel_mm[j] = moving(j) ? axis_step(j, position_mm[j], cy) : 0.0;
}

// One cycle of axis j: the travel (signed, mm).
double JogUnit::axis_step(std::size_t j, double position_mm, Cycle& cy) noexcept {
  const JogAxisSettings& s = settings_[j];
  AxisJog& g = jogs_[j];
  const double dv_mm_s = s.a_max_mm_s2 * cy.dt_s;
  const double limit_mm = g.direction > 0 ? s.sw_limit_pos_mm : s.sw_limit_neg_mm;
  const double room_mm = std::max(0.0, (limit_mm - position_mm) * g.direction);
  const bool to_step_end = g.kind == JogRequest::Kind::increment && g.left_mm <= room_mm;
  const double goal_mm = to_step_end ? std::max(0.0, g.left_mm) : room_mm;
  // Towards the wanted speed within a_max, never faster than the axis can
  // still stop within the goal. Under ACTIVE_EXTENDED (P-CHAN-00181) the
  // rapid override scales a continuous jog; a jog at 0 % holds, not ends.
  const bool overridden = rapid_mode_ == RapidOverrideMode::active_extended && g.kind == JogRequest::Kind::continuous;
  const double wanted_mm_s =
      overridden ? g.wanted_mm_s * std::clamp(cy.in.rapid_override_pct, 0.0, 100.0) / 100.0 : g.wanted_mm_s;
  double v_mm_s = wanted_mm_s >= g.v_mm_s ? std::min(g.v_mm_s + dv_mm_s, wanted_mm_s)
                                          : std::max(g.v_mm_s - dv_mm_s, wanted_mm_s);
  v_mm_s = std::min(v_mm_s, motion::discrete_brake_velocity(goal_mm, s.a_max_mm_s2, cy.dt_s));
  const double travel_mm = std::min(v_mm_s * cy.dt_s, goal_mm);  // the last cycle lands exactly
  g.v_mm_s = cy.dt_s > 0 ? travel_mm / cy.dt_s : 0.0;
  g.left_mm -= travel_mm;
  const double signed_travel_mm = travel_mm * g.direction;  // end() forgets the direction
  const bool reached = travel_mm >= goal_mm && g.kind != JogRequest::Kind::stop && g.wanted_mm_s > 0;
  if (reached) end(j, !to_step_end, cy);
  else if (g.wanted_mm_s <= 0 && g.v_mm_s <= 0) end(j, false, cy);
  return signed_travel_mm;
}

// The jog of axis j is over; its last step's speed and direction stay for
// a jog that starts in the next cycle (take()).
void JogUnit::end(std::size_t j, bool at_limit, Cycle& cy) noexcept {
  AxisJog& g = jogs_[j];
  g.kind = JogRequest::Kind::none;
  g.wanted_mm_s = 0;
  g.left_mm = 0;
  active_ &= ~(1u << j);
  stopping_now_ |= 1u << j;
  if (at_limit) warn(ErrorId::KernelJogSoftLimit, cy);
}

void JogUnit::release_all() noexcept {
  for (std::size_t j = 0; j < kMaxAxes; ++j) {
    if (!moving(j)) continue;
    jogs_[j].wanted_mm_s = 0;
    jogs_[j].kind = JogRequest::Kind::stop;
  }
}

}  // namespace nck::kernel
