// Synchronous operation in the cycle (ax_link.hpp): enabling and disabling
// coupling groups, keeping other channels off linked spindles, and moving
// path-axis slaves with their master every cycle. The spindle slaves got
// their own actions from preparation (planner_axlink.cpp).
#include "channel.hpp"

namespace nck::kernel {

bool Channel::linked_elsewhere(std::int8_t spindle, const ChannelContext& ctx) const noexcept {
  if (spindle < 0 || static_cast<std::size_t>(spindle) >= ctx.spindle_count) return false;
  const SpindleUnit& u = ctx.spindles[spindle];
  return u.link_channel != 0 && u.link_channel != number_;
}

// At a block's start: groups off, then the group on. False: an error was raised.
bool Channel::take_ax_link(const Command& c, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept {
  if (!c.link.any()) return true;
  for (std::size_t i = links_.size(); i-- > 0;)
    if ((c.link.disable_mask >> links_[i].cmd.group) & 1u) dissolve_link(i, LinkReason::program, t_s, sink, ctx);
  if (!c.link.enable) return true;
  for (const AxLinkPair& p : c.link.pairs)
    if (p.spindle && (linked_elsewhere(p.slave, ctx) || linked_elsewhere(p.master, ctx))) {
      raise(ErrorId::AxLinkOtherChannel, kNoMessage, t_s, sink, ctx);
      return false;
    }
  ActiveLink l;
  l.cmd = c.link;
  for (std::size_t k = 0; k < c.link.pairs.size(); ++k) {
    const AxLinkPair& p = c.link.pairs[k];
    if (!p.spindle) {  // the slave keeps its distance from the master (gantry: where both stand)
      l.base_slave_mm[k] = pos_[static_cast<std::size_t>(p.slave)];
      l.base_master_mm[k] = pos_[static_cast<std::size_t>(p.master)];
      continue;
    }
    for (std::int8_t s : {p.slave, p.master}) {
      if (s < 0 || static_cast<std::size_t>(s) >= ctx.spindle_count) continue;
      ctx.spindles[s].link_channel = number_;
      ++ctx.spindles[s].link_groups;
    }
  }
  if (!links_.push_back(l)) {  // the planner allows one entry per group number
    raise(ErrorId::AxLinkGroupRange, kNoMessage, t_s, sink, ctx);
    return false;
  }
  Event e = event(EventKind::link, t_s);
  e.message_index = l.cmd.payload;
  e.link_group = l.cmd.group;
  e.link_on = true;
  e.link_reason = static_cast<std::uint8_t>(LinkReason::program);
  sink.emit(e);
  return true;
}

void Channel::dissolve_link(std::size_t i, LinkReason why, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept {
  const ActiveLink& l = links_[i];
  for (const AxLinkPair& p : l.cmd.pairs) {
    if (!p.spindle) continue;
    for (std::int8_t s : {p.slave, p.master}) {
      if (s < 0 || static_cast<std::size_t>(s) >= ctx.spindle_count) continue;
      SpindleUnit& u = ctx.spindles[s];
      if (u.link_groups > 0 && --u.link_groups == 0) u.link_channel = 0;
    }
  }
  Event e = event(EventKind::link, t_s);
  e.message_index = l.cmd.payload;
  e.link_group = l.cmd.group;
  e.link_on = false;
  e.link_reason = static_cast<std::uint8_t>(why);
  sink.emit(e);
  for (std::size_t k = i + 1; k < links_.size(); ++k) links_[k - 1] = links_[k];
  links_.pop_back();
}

// Program end dissolves the links unless P-CHAN-00105; abort and reset always.
void Channel::dissolve_links(EndReason end, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept {
  const bool regular = end == EndReason::m30 || end == EndReason::m2;
  if (regular && preserve_links_) return;
  const LinkReason why = regular ? LinkReason::program_end : end == EndReason::reset ? LinkReason::reset : LinkReason::abort;
  while (!links_.empty()) dissolve_link(links_.size() - 1, why, t_s, sink, ctx);
}

// Each cycle: slave = where it stood + (master - where the master stood) * ratio.
void Channel::follow_axis_links() noexcept {
  for (const ActiveLink& l : links_)
    for (std::size_t k = 0; k < l.cmd.pairs.size(); ++k) {
      const AxLinkPair& p = l.cmd.pairs[k];
      if (p.spindle) continue;
      pos_[static_cast<std::size_t>(p.slave)] =
          l.base_slave_mm[k] + (pos_[static_cast<std::size_t>(p.master)] - l.base_master_mm[k]) * p.ratio;
    }
}

}  // namespace nck::kernel
