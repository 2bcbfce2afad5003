#include "nck/kernel/hsc_chain.hpp"

#include <algorithm>

#include "nck/kernel/braking_reserve.hpp"
#include "nck/motion/limits.hpp"

namespace nck::kernel {

// TRAPEZ only: the chain is planned as one TRAPEZ move (a SIN2 ramp
// planned again from a state of the ramp under way overshoots).
bool chains_as_spline(const Motion& m) noexcept {
  return m.limits.slope == SlopeProfile::trapez && m.path.kind == motion::SegmentKind::cubic;
}

bool chains(const Motion& m) noexcept { return m.limits.slope == SlopeProfile::hsc || chains_as_spline(m); }

namespace {

double cruise_of(const Motion& m) noexcept { return std::min(m.v_cmd_mm_s, m.limits.v_max_mm_s); }

// Whether m may join a chain of cruise v after `last` (the chain's last
// motion): the transition passes at both motions' speed, and m's is not
// below the chain's (so neither is the transition's).
bool joins(const Motion& last, const Motion& m, double v_cruise_mm_s) noexcept {
  return last.passes_at_cruise && chains(m) && (m.limits.slope == SlopeProfile::hsc || chains_as_spline(last)) &&
         m.trafo.kind == motion::CaxTrafoKind::none && !m.measure && cruise_of(m) >= v_cruise_mm_s &&
         motion::valid(m.limits);
}

motion::PathLimits merged(const motion::PathLimits& a, const motion::PathLimits& b) noexcept {
  motion::PathLimits l = a;
  l.v_max_mm_s = std::min(a.v_max_mm_s, b.v_max_mm_s);
  l.a_acc_mm_s2 = std::min(a.a_acc_mm_s2, b.a_acc_mm_s2);
  l.a_dec_mm_s2 = std::min(a.a_dec_mm_s2, b.a_dec_mm_s2);
  l.tr = motion::longest(a.tr, b.tr);
  return l;
}

}  // namespace

HscChain hsc_chain(const Motion& current, double length_mm, const CommandQueue& queued, double dt_s) noexcept {
  HscChain h;
  const std::size_t seen = chain_view(queued);
  h.queued_seen = seen;
  const double v_cruise = cruise_of(current);
  motion::PathChain c{length_mm, current.limits, 0.0};
  const Motion* last = &current;
  std::size_t after_last = 0;  // index in queued of the first command after `last`
  std::size_t members = 1;
  for (std::size_t i = 0; i < seen; ++i) {
    const Command& cmd = queued.at(i);
    if (cmd.is<Nop>()) continue;
    const Motion* m = cmd.as<Motion>();
    if (!m || !joins(*last, *m, v_cruise)) break;
    c.length_mm += m->path.length_mm;
    c.limits = merged(c.limits, m->limits);
    last = m;
    after_last = i + 1;
    ++members;
  }
  // Everything queued after `last` is blocks without motion (or nothing):
  // the queue ends inside the chain's reach, a stop until more comes.
  bool more = false;
  for (std::size_t i = after_last; i < seen && !more; ++i) more = !queued.at(i).is<Nop>();
  h.open = !more;
  if (members == 1) return h;  // nothing joins (yet): the motion's own plan
  c.v_end_mm_s = more ? std::min(last->v_end_mm_s, reserve_end_speed(*last, queued, dt_s, after_last, seen)) : 0.0;
  // Lowered by the braking reserve: raised again as preparation queues more.
  h.open = h.open || c.v_end_mm_s < last->v_end_mm_s;
  h.chain = c;
  return h;
}

}  // namespace nck::kernel
