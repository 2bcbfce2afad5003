#include "axis_link_unit.hpp"

namespace nck::kernel {

bool AxisLinkUnit::linked_elsewhere(std::int8_t spindle, const Cycle& cy) const noexcept {
  const SpindleUnit* u = cy.machine.spindle(spindle);
  return u && linked_to_other_channel(*u, cy.channel);
}

Fault AxisLinkUnit::start(const LinkCommand& c, const motion::AxisVector& pos_mm, Cycle& cy) noexcept {
  if (!c.any()) return {};
  for (std::size_t i = links_.size(); i-- > 0;)
    if ((c.disable_mask >> links_[i].cmd.group) & 1u) dissolve(i, LinkReason::program, cy);
  if (!c.enable) return {};
  for (const AxLinkPair& p : c.pairs)
    if (p.spindle && (linked_elsewhere(p.slave, cy) || linked_elsewhere(p.master, cy)))
      return {ErrorId::AxLinkOtherChannel};
  ActiveLink l;
  l.cmd = c;
  for (std::size_t k = 0; k < c.pairs.size(); ++k) {
    const AxLinkPair& p = c.pairs[k];
    if (!p.spindle) {  // the slave keeps its distance from the master (gantry: where both stand)
      l.base_slave_mm[k] = pos_mm[static_cast<std::size_t>(p.slave)];
      l.base_master_mm[k] = pos_mm[static_cast<std::size_t>(p.master)];
      continue;
    }
    for (std::int8_t s : {p.slave, p.master}) {
      if (SpindleUnit* u = cy.machine.spindle(s)) {
        u->link_channel = cy.channel;
        ++u->link_groups;
      }
    }
  }
  if (!links_.push_back(l)) return {ErrorId::AxLinkGroupRange};  // the planner allows one entry per group number
  emit(l, true, LinkReason::program, cy);
  return {};
}

void AxisLinkUnit::emit(const ActiveLink& l, bool on, LinkReason why, Cycle& cy) const noexcept {
  cy.emit(LinkEvent{l.cmd.group, on, why, l.cmd.payload});
}

void AxisLinkUnit::dissolve(std::size_t i, LinkReason why, Cycle& cy) noexcept {
  const ActiveLink& l = links_[i];
  for (const AxLinkPair& p : l.cmd.pairs) {
    if (!p.spindle) continue;
    for (std::int8_t s : {p.slave, p.master}) {
      SpindleUnit* u = cy.machine.spindle(s);
      if (u && u->link_groups > 0 && --u->link_groups == 0) u->link_channel = 0;
    }
  }
  emit(l, false, why, cy);
  for (std::size_t k = i + 1; k < links_.size(); ++k) links_[k - 1] = links_[k];
  links_.pop_back();
}

void AxisLinkUnit::end(EndReason end, Cycle& cy) noexcept {
  const bool regular = end == EndReason::m30 || end == EndReason::m2;
  if (regular && preserve_) return;
  const LinkReason why = regular                    ? LinkReason::program_end
                         : end == EndReason::reset ? LinkReason::reset
                                                   : LinkReason::abort;
  while (!links_.empty()) dissolve(links_.size() - 1, why, cy);
}

// slave = where it stood + (master - where the master stood) * ratio.
void AxisLinkUnit::follow_links(motion::AxisVector& pos_mm) const noexcept {
  for (const ActiveLink& l : links_)
    for (std::size_t k = 0; k < l.cmd.pairs.size(); ++k) {
      const AxLinkPair& p = l.cmd.pairs[k];
      if (p.spindle) continue;
      pos_mm[static_cast<std::size_t>(p.slave)] =
          l.base_slave_mm[k] + (pos_mm[static_cast<std::size_t>(p.master)] - l.base_master_mm[k]) * p.ratio;
    }
}

}  // namespace nck::kernel
