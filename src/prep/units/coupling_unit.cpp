// Planning of synchronous operation; see coupling_unit.hpp.
#include "nck/prep/units/coupling_unit.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace nck::prep {
namespace {

// The channel spindle with log_achs_nr = main_spindle_ax_nr, else the first (-1: none).
int configured_main_spindle(const config::ChannelConfig& channel) {
  int main = -1;
  for (std::size_t i = 0; i < channel.spindles.size(); ++i)
    if (channel.spindles[i].log_axis_nr == channel.main_spindle_ax_nr) main = static_cast<int>(i);
  if (main < 0 && !channel.spindles.empty()) main = 0;
  return main;
}

// The coupling groups' diagnostics carry no location: the block's.
std::unexpected<Diagnostic> at_block(Diagnostic d, const nc::Block& b) {
  d.loc.line = b.line;
  return std::unexpected(std::move(d));
}

}  // namespace

CouplingUnit::CouplingUnit(const config::ChannelConfig& channel, const std::vector<std::int8_t>& spindles)
    : configured_main_spindle_(configured_main_spindle(channel)),
      groups_(channel, configured_main_spindle_),
      kernel_spindles_(spindles) {}

PlanResult CouplingUnit::plan(const nc::Block& b, PlannedCommand& c, PlanContext& ctx) {
  if (b.hash)
    if (auto r = plan_hash(b, c, ctx); !r) return r;
  // A slave is moved by its master only.
  for (std::size_t j = 0; j < ctx.n_axes; ++j)
    if (b.axes[j] && groups_.axis_is_slave(static_cast<int>(j)))
      return block_error(ErrorId::AxLinkSlaveProgrammed, b,
                         fmt::format("{} is the slave of an enabled coupling group", ctx.channel.axes[j].name));
  for (const nc::SpindleCommand& s : b.spindles)
    if (s.spindle_index && groups_.spindle_is_slave(*s.spindle_index))
      return block_error(ErrorId::AxLinkSlaveProgrammed, b,
                         fmt::format("{} is the slave spindle of an enabled coupling group",
                                     ctx.channel.spindles[*s.spindle_index].name));
  return {};
}

// The # commands: definitions, enabling, disabling, and #MAIN SPINDLE's rule.
PlanResult CouplingUnit::plan_hash(const nc::Block& b, PlannedCommand& c, PlanContext& ctx) {
  const config::ChannelConfig& channel = ctx.channel;
  const nc::HashCommand& h = *b.hash;
  if (const auto* s = std::get_if<nc::SetAxLink>(&h)) {
    if (auto r = groups_.define(*s); !r) return at_block(r.error(), b);
  } else if (const auto* m = std::get_if<nc::MainSpindle>(&h)) {
    int target = configured_main_spindle_;
    for (std::size_t i = 0; i < channel.spindles.size(); ++i)
      if ((m->name && channel.spindles[i].name == *m->name) ||
          (m->log_axis_nr && channel.spindles[i].log_axis_nr == static_cast<std::uint32_t>(*m->log_axis_nr)))
        target = static_cast<int>(i);
    if (auto r = groups_.change_main_spindle(target); !r) return at_block(r.error(), b);
  } else if (const auto* en = std::get_if<nc::EnableAxLink>(&h)) {
    auto r = groups_.enable(en->group);
    if (!r) return at_block(r.error(), b);
    const int g = en->group.value_or(0);
    LinkPayload payload{g, {}};
    kernel::LinkCommand link;
    link.enable = true;
    link.group = static_cast<std::int8_t>(g);
    const motion::AxisVector& mcs = ctx.planned.mcs;
    for (const LinkPairDef& p : (*r)->pairs) {
      payload.pairs.emplace_back(groups_.member_name(p.slave), groups_.member_name(p.master));
      kernel::AxLinkPair k;
      k.spindle = p.slave.spindle;
      k.slave = static_cast<std::int8_t>(p.slave.spindle ? kernel_spindles_[static_cast<std::size_t>(p.slave.index)] : p.slave.index);
      k.master = static_cast<std::int8_t>(p.master.spindle ? kernel_spindles_[static_cast<std::size_t>(p.master.index)] : p.master.index);
      k.gantry = p.gantry;
      k.ratio = p.ratio;
      (void)link.pairs.push_back(k);
      if (!p.slave.spindle)
        axis_follow_.push_back({g, p.slave.index, p.master.index, mcs[static_cast<std::size_t>(p.slave.index)],
                                mcs[static_cast<std::size_t>(p.master.index)], p.ratio});
    }
    link.payload = ctx.store.add_link(std::move(payload));
    c.attach(link);
  } else if (const auto* d = std::get_if<nc::DisableAxLink>(&h)) {
    auto r = groups_.disable(*d);
    if (!r) return at_block(r.error(), b);
    if (*r != 0) {
      kernel::LinkCommand link;
      link.disable_mask = *r;
      c.attach(link);
    }
    std::erase_if(axis_follow_, [&](const AxisFollow& f) { return ((*r >> f.group) & 1u) != 0; });
  }
  return {};
}

// The master's speed, M3/M4/M5 and M19 (POS) are programmed for every
// slave too, as the slave's own spindle command in the same block: the
// spindle planning then gives each slave its own synchronisation, PLC
// output and gear checks from its channel list (FCT-S1 2.8.3: no separate
// commands for the slaves; the technology functions of master and slaves
// are synchronised together, the block waits for all of them).
const nc::Block& CouplingUnit::with_slaves(const nc::Block& b, nc::Block& scratch,
                                           const config::ChannelConfig& channel) const {
  bool any = false;
  for (const nc::SpindleCommand& s : b.spindles)
    if (s.spindle_index && !groups_.slaves_of_spindle(*s.spindle_index).empty()) any = true;
  if (!any) return b;
  scratch = b;
  for (const nc::SpindleCommand& s : b.spindles) {
    if (!s.spindle_index) continue;
    for (int slave : groups_.slaves_of_spindle(*s.spindle_index)) {
      if (s.m == nc::SpindleM::none && !s.rev_rpm && !s.pos_deg) continue;
      nc::SpindleCommand c;
      c.name = channel.spindles[static_cast<std::size_t>(slave)].name;
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
void CouplingUnit::end_program(const nc::Block& b) {
  if (!b.program_end) return;
  (void)groups_.disable_all();
  axis_follow_.clear();
}

void CouplingUnit::follow(PlanContext& ctx) const {
  if (axis_follow_.empty()) return;
  motion::AxisVector& mcs = ctx.planned.mcs;
  for (const AxisFollow& f : axis_follow_)
    mcs[static_cast<std::size_t>(f.slave)] =
        f.base_slave_mm + (mcs[static_cast<std::size_t>(f.master)] - f.base_master_mm) * f.ratio;
  ctx.planned.reread(ctx.frames);
}

}  // namespace nck::prep
