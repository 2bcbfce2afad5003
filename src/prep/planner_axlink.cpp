// Planning of synchronous operation (facts B18, spindle-link seed, FCT-S1
// 2.8.3): #SET AX LINK / #ENABLE AX LINK / #DISABLE AX LINK become
// kernel::LinkCommand; while a spindle group is enabled, the master's speed,
// M3/M4/M5 and M19 are commanded to its slaves in the same block (each
// slave's own spindle command, so each has its own override, feedhold,
// dynamics and wait); path-axis slaves follow their master (the kernel moves them every
// cycle; planned_mcs() follows here so later blocks start where they stand).
#include <algorithm>
#include <fmt/format.h>

#include "nck/prep/planner.hpp"

namespace nck::prep {
void Planner::init_ax_links(const std::vector<std::int8_t>& spindles) {
  kernel_spindles_ = spindles;
  for (std::size_t i = 0; i < channel_.spindles.size(); ++i)
    if (channel_.spindles[i].log_axis_nr == channel_.main_spindle_ax_nr) configured_main_spindle_ = static_cast<int>(i);
  if (configured_main_spindle_ < 0 && !channel_.spindles.empty()) configured_main_spindle_ = 0;
  links_.emplace(channel_, configured_main_spindle_);
}

// Spindle-syntax functions nck does not model; named, with their own ID.
std::string Planner::spindle_out_of_scope(const nc::Block& b) const {
  for (const nc::SpindleCommand& s : b.spindles) {
    if (s.callax || s.putax) return fmt::format("{}: CALLAX / PUTAX (axis exchange) are not modelled by nck", s.name);
    if (s.feed_link) return fmt::format("{}: FEED_LINK (spindle speed from the path feed) is not modelled by nck", s.name);
    if (s.override_speed_fact_pct)
      return fmt::format("{}: OVERRIDE SPEED_FACT (programmed spindle override) is not modelled by nck", s.name);
  }
  return {};
}

std::optional<Command> Planner::plan_ax_link(const nc::Block& b, Command& c) {
  auto err = [&](const LinkError& e) { return error_command(e.id, e.message, b.file_id, b.line); };
  if (b.hash) {
    if (auto e = ax_link_command(b, c)) return e;
  }
  // A slave is moved by its master only.
  for (std::size_t j = 0; j < n_axes_; ++j)
    if (b.axes[j] && links_->axis_is_slave(static_cast<int>(j)))
      return err({ErrorId::AxLinkSlaveProgrammed, fmt::format("{} is the slave of an enabled coupling group", channel_.axes[j].name)});
  for (const nc::SpindleCommand& s : b.spindles)
    if (s.spindle_index && links_->spindle_is_slave(*s.spindle_index))
      return err({ErrorId::AxLinkSlaveProgrammed,
                  fmt::format("{} is the slave spindle of an enabled coupling group", channel_.spindles[*s.spindle_index].name)});
  return std::nullopt;
}

// The # commands: definitions, enabling, disabling, and #MAIN SPINDLE's rule.
std::optional<Command> Planner::ax_link_command(const nc::Block& b, Command& c) {
  auto err = [&](const LinkError& e) { return error_command(e.id, e.message, b.file_id, b.line); };
  const nc::HashCommand& h = *b.hash;
  if (const auto* s = std::get_if<nc::SetAxLink>(&h)) {
    if (auto r = links_->define(*s); !r) return err(r.error());
  } else if (const auto* m = std::get_if<nc::MainSpindle>(&h)) {
    int target = configured_main_spindle_;
    for (std::size_t i = 0; i < channel_.spindles.size(); ++i)
      if ((m->name && channel_.spindles[i].name == *m->name) ||
          (m->log_axis_nr && channel_.spindles[i].log_axis_nr == static_cast<std::uint32_t>(*m->log_axis_nr)))
        target = static_cast<int>(i);
    if (auto r = links_->change_main_spindle(target); !r) return err(r.error());
  } else if (const auto* en = std::get_if<nc::EnableAxLink>(&h)) {
    auto r = links_->enable(en->group);
    if (!r) return err(r.error());
    const int g = en->group.value_or(0);
    LinkPayload payload{g, {}};
    c.link.enable = true;
    c.link.group = static_cast<std::int8_t>(g);
    for (const LinkPairDef& p : (*r)->pairs) {
      payload.pairs.emplace_back(links_->member_name(p.slave), links_->member_name(p.master));
      kernel::AxLinkPair k;
      k.spindle = p.slave.spindle;
      k.slave = static_cast<std::int8_t>(p.slave.spindle ? kernel_spindles_[static_cast<std::size_t>(p.slave.index)] : p.slave.index);
      k.master = static_cast<std::int8_t>(p.master.spindle ? kernel_spindles_[static_cast<std::size_t>(p.master.index)] : p.master.index);
      k.gantry = p.gantry;
      k.ratio = p.ratio;
      (void)c.link.pairs.push_back(k);
      if (!p.slave.spindle)
        axis_follow_.push_back({g, p.slave.index, p.master.index, mcs_[static_cast<std::size_t>(p.slave.index)],
                                mcs_[static_cast<std::size_t>(p.master.index)], p.ratio});
    }
    c.link.payload = store_.add_link(std::move(payload));
  } else if (const auto* d = std::get_if<nc::DisableAxLink>(&h)) {
    auto r = links_->disable(*d);
    if (!r) return err(r.error());
    c.link.disable_mask = *r;
    std::erase_if(axis_follow_, [&](const AxisFollow& f) { return ((*r >> f.group) & 1u) != 0; });
  }
  return std::nullopt;
}

// The master's speed, M3/M4/M5 and M19 (POS) are programmed for every
// slave too, as the slave's own spindle command in the same block: the
// spindle planning then gives each slave its own synchronisation, PLC
// output and gear checks from its channel list (FCT-S1 2.8.3: no separate
// commands for the slaves; the technology functions of master and slaves
// are synchronised together, the block waits for all of them).
const nc::Block& Planner::with_slaves(const nc::Block& b, nc::Block& scratch) const {
  bool any = false;
  for (const nc::SpindleCommand& s : b.spindles)
    if (s.spindle_index && !links_->slaves_of_spindle(*s.spindle_index).empty()) any = true;
  if (!any) return b;
  scratch = b;
  for (const nc::SpindleCommand& s : b.spindles) {
    if (!s.spindle_index) continue;
    for (int slave : links_->slaves_of_spindle(*s.spindle_index)) {
      if (s.m == nc::SpindleM::none && !s.rev_rpm && !s.pos_deg) continue;
      nc::SpindleCommand c;
      c.name = channel_.spindles[static_cast<std::size_t>(slave)].name;
      c.target = c.name;
      c.spindle_index = static_cast<std::uint8_t>(slave);
      c.column = s.column;
      c.m = s.m;
      c.direction = s.direction;
      c.rev_rpm = s.rev_rpm;
      c.pos_deg = s.pos_deg;
      c.g167 = s.g167;
      scratch.spindles.push_back(std::move(c));
    }
  }
  return scratch;
}

// M30 / M2 dissolve the links in the kernel (unless P-CHAN-00105); the
// planning of this program ends with them.
void Planner::end_ax_links(const nc::Block& b) {
  if (!b.program_end) return;
  (void)links_->disable_all();
  axis_follow_.clear();
}

// Where the slaves stand once the block has run: as the kernel moves them.
void Planner::follow_axis_links() {
  if (axis_follow_.empty()) return;
  for (const AxisFollow& f : axis_follow_)
    mcs_[static_cast<std::size_t>(f.slave)] =
        f.base_slave_mm + (mcs_[static_cast<std::size_t>(f.master)] - f.base_master_mm) * f.ratio;
  pcs_ = frames_.to_pcs(mcs_);
}

}  // namespace nck::prep
