#include "nck/kernel/braking_reserve.hpp"

#include <algorithm>
#include <array>

#include "nck/motion/junction.hpp"
#include "nck/motion/path_profile.hpp"

namespace nck::kernel {

namespace {

// Entering m to leave it at v_exit: its own profile's law.
double entry_speed(const Motion& m, double v_exit_mm_s, double dt_s) noexcept {
  if (jerk_limited(m.limits.slope) && motion::valid(motion::jerk_limits(m.limits)))
    return motion::jerk_entry_velocity(m.path.length_mm, v_exit_mm_s, motion::jerk_limits(m.limits));
  return motion::entry_velocity_limit(m.path.length_mm, v_exit_mm_s, m.limits.a_dec_mm_s2, dt_s);
}

// A jerk-limited profile brings its acceleration to 0 at every block end,
// so the path cannot brake across a chain of short blocks in one ramp. The
// look-ahead planned each end speed so that the next block can slow to its
// own planned end speed; only the last queued motion must now also stop:
// lower what it cannot brake from, back along the queue until a planned
// end speed holds again (usually one or two blocks).
double jerk_reserve_end_speed(const Motion& current, const CommandQueue& queued, double dt_s,
                              std::size_t first, std::size_t end) noexcept {
  const double planned = current.v_end_mm_s;
  std::array<const Motion*, kCommandQueueLength> chain{};
  std::size_t n = 0;
  for (std::size_t i = first; i < end && n < chain.size(); ++i) {
    const Command& c = queued.at(i);
    if (c.is<Nop>()) continue;
    const Motion* m = c.as<Motion>();
    if (!m || !(m->v_end_mm_s > 0.0)) return planned;  // a planned stop is queued: the plan holds
    chain[n++] = m;
  }
  double v_exit = 0.0;  // after the last queued motion nothing is known: a stop
  for (std::size_t i = n; i-- > 0;) {
    const double v_entry = entry_speed(*chain[i], v_exit, dt_s);
    const double planned_before = i > 0 ? chain[i - 1]->v_end_mm_s : planned;
    if (v_entry >= planned_before) return planned;  // from here back the plan holds
    v_exit = v_entry;
  }
  return std::min(planned, v_exit);
}

}  // namespace

double reserve_end_speed(const Motion& current, const CommandQueue& queued, double dt_s, std::size_t first,
                         std::size_t end) noexcept {
  const double planned = current.v_end_mm_s;
  if (!(planned > 0.0)) return 0.0;
  end = std::min(end, queued.size());
  if (jerk_limited(current.limits.slope)) return jerk_reserve_end_speed(current, queued, dt_s, first, end);
  double a_mm_s2 = current.limits.a_dec_mm_s2;  // the gentlest deceleration of the chain
  double length_mm = 0.0;                       // queued path to stop within
  // Braking across its end, the path passes on no faster than its staircase allows there.
  const double passing = current.brake_beyond_mm > 0.0
                             ? std::min(planned, motion::discrete_brake_velocity(current.brake_beyond_mm, a_mm_s2, dt_s))
                             : planned;
  for (std::size_t i = first; i < end; ++i) {
    const Command& c = queued.at(i);
    if (c.is<Nop>()) continue;  // a block without motion: the path passes through it
    // Anything else than a motion was planned with a stop before it.
    const Motion* m = c.as<Motion>();
    if (!m) return planned;
    length_mm += m->path.length_mm;
    a_mm_s2 = std::min(a_mm_s2, m->limits.a_dec_mm_s2);
    // A planned stop within the queue: the planner's own braking holds.
    if (!(m->v_end_mm_s > 0.0)) return planned;
    if (motion::discrete_brake_distance(passing, a_mm_s2, dt_s) <= length_mm) return planned;
  }
  return std::min(planned, motion::discrete_brake_velocity(length_mm, a_mm_s2, dt_s));
}

}  // namespace nck::kernel
