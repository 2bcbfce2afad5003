#include "nck/kernel/braking_reserve.hpp"

#include <algorithm>

#include "nck/motion/path_profile.hpp"

namespace nck::kernel {

double reserve_end_speed(const Motion& current, const CommandQueue& queued, double dt_s) noexcept {
  const double planned = current.v_end_mm_s;
  if (!(planned > 0.0)) return 0.0;
  double a_mm_s2 = current.limits.a_dec_mm_s2;  // the gentlest deceleration of the chain
  double length_mm = 0.0;                       // queued path to stop within
  const std::size_t n = queued.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Command& c = queued.at(i);
    if (c.is<Nop>()) continue;  // a block without motion: the path passes through it
    // Anything else than a motion was planned with a stop before it.
    const Motion* m = c.as<Motion>();
    if (!m) return planned;
    length_mm += m->path.length_mm;
    a_mm_s2 = std::min(a_mm_s2, m->limits.a_dec_mm_s2);
    // A planned stop within the queue: the planner's own braking holds.
    if (!(m->v_end_mm_s > 0.0)) return planned;
    if (motion::discrete_brake_distance(planned, a_mm_s2, dt_s) <= length_mm) return planned;
  }
  return std::min(planned, motion::discrete_brake_velocity(length_mm, a_mm_s2, dt_s));
}

}  // namespace nck::kernel
