#include "nck/prep/braking_staircase.hpp"

#include <algorithm>

#include "nck/motion/junction.hpp"
#include "nck/motion/path_profile.hpp"

namespace nck::prep {
namespace {

// What c can brake with from its first step on (passing in from a fillet:
// what the fillet's turn leaves of a_max).
double first_step_deceleration(const PlannedCommand& c) {
  return c.pass_in_limited ? std::min(c.limits.a_dec_mm_s2, c.start_a_mm_s2) : c.limits.a_dec_mm_s2;
}

// holding_entry_limit's margins for a motion of length_mm that brakes
// across its end to standstill beyond_mm past it.
double across_entry_limit(double length_mm, double beyond_mm, double a_mm_s2, double dt_s) {
  const double v = motion::discrete_brake_velocity(length_mm + beyond_mm, a_mm_s2, dt_s);
  const double shorter = std::max(length_mm - v * dt_s, 0.0);
  return std::max(motion::discrete_brake_velocity(shorter + beyond_mm, a_mm_s2, dt_s) - a_mm_s2 * dt_s, 0.0);
}

}  // namespace

double holding_entry_limit(const PlannedCommand& c, double dt_s) {
  const double length = c.segment.length(), a = c.limits.a_dec_mm_s2;
  // A jerk-limited profile passes a transition at its planned speed with
  // acceleration 0 and carries the exact time: no margins.
  if (jerk_limited(c.limits.slope) && motion::valid(motion::jerk_limits(c.limits)))
    return motion::jerk_entry_velocity(length, c.v_end_mm_s, motion::jerk_limits(c.limits));
  const double v = motion::entry_velocity_limit(length, c.v_end_mm_s, a, dt_s);
  const double shorter = std::max(length - v * dt_s, 0.0);
  return std::max(motion::entry_velocity_limit(shorter, c.v_end_mm_s, a, dt_s) - a * dt_s, 0.0);
}

Staircase settle(const PlannedCommand& c, std::uint64_t seq, EndCaps caps, const Staircase* next, double dt_s) {
  const double length = c.segment.length();
  // Holding: the staircase comes to rest where the profile's would
  // (pass_brake_distance); a motion before it brakes towards the same
  // point, no harder than this one's first step can.
  Staircase s{holding_entry_limit(c, dt_s),
              length + motion::pass_brake_distance(c.v_end_mm_s, c.limits.a_dec_mm_s2, dt_s),
              first_step_deceleration(c),
              0,
              seq,
              false,
              c.limits.slope == SlopeProfile::step};
  if (!next || !next->step || !s.step || !(c.v_end_mm_s > 0)) return s;
  // It passes on no faster than its corner allows (held there, as a
  // ceiling) nor than next's staircase: the lower curve of the two. Below
  // both curves all along, entering at no more than the ceiling is always
  // possible (the margins are not paid again at every ceiling).
  const double a = std::min(s.a_mm_s2, next->a_mm_s2);
  const double cap = caps.through_mm_s;
  const double beyond = std::min(next->stand_mm, motion::pass_brake_distance(cap, a, dt_s));
  if (!(beyond > 0)) return s;
  const double v = std::max(across_entry_limit(length, beyond, a, dt_s),
                            std::min(cap, across_entry_limit(length, next->stand_mm, a, dt_s)));
  if (!(v > s.entry_mm_s)) return s;
  return Staircase{v, length + beyond, a, next->stand_mm, next->reference, true, true};
}

}  // namespace nck::prep
