// Coupling groups and their rules (spindle_link seed, FCT-S1 §2.8.3,
// docs/nc-language.md "Synchronous operation"); see ax_link_groups.hpp.
#include "nck/prep/ax_link_groups.hpp"

#include <algorithm>
#include <charconv>
#include <fmt/format.h>

namespace nck::prep {
namespace {

bool iequal(const std::string& a, const std::string& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](char x, char y) { return std::toupper(static_cast<unsigned char>(x)) ==
                                                std::toupper(static_cast<unsigned char>(y)); });
}

// The line is the block's: the planner sets it when it makes the error command.
std::unexpected<Diagnostic> fail(ErrorId id, std::string msg) {
  return std::unexpected(make_diagnostic(id, {}, std::move(msg)));
}

}  // namespace

AxLinkGroups::AxLinkGroups(const config::ChannelConfig& channel, int main_spindle)
    : channel_(channel), groups_(kernel::kMaxLinkGroupNr + 1), main_spindle_(main_spindle) {
  for (const config::LinkPair& p : channel.default_link_group.pairs) {
    auto slave = resolve(std::to_string(p.slave_nr), true);
    auto master = resolve(std::to_string(p.master_nr), true);
    // config checked the pairs (ConfigLinkPair); the mode decides the kind
    if (!slave || !master || slave->spindle != (p.mode == 1) || master->spindle != (p.mode == 1)) continue;
    groups_[0].pairs.push_back(LinkPairDef{*slave, *master});
  }
}

std::string AxLinkGroups::member_name(const LinkMember& m) const {
  if (m.spindle) return channel_.spindles[static_cast<std::size_t>(m.index)].name;
  return channel_.axes[static_cast<std::size_t>(m.index)].name;
}

// A name (path axis, spindle, or the main spindle's name) or, with NBR, a
// logical axis number of the channel.
std::expected<LinkMember, Diagnostic> AxLinkGroups::resolve(const std::string& token, bool by_number) const {
  const std::size_t n_axes = channel_.axes.size();
  if (by_number) {
    std::uint32_t nr = 0;
    auto [p, ec] = std::from_chars(token.data(), token.data() + token.size(), nr);
    if (ec == std::errc() && p == token.data() + token.size()) {
      for (std::size_t i = 0; i < channel_.spindles.size(); ++i)
        if (channel_.spindles[i].log_axis_nr == nr) return LinkMember{true, static_cast<int>(i)};
      for (std::size_t j = 0; j < n_axes; ++j)
        if (static_cast<int>(j) != channel_.c_axis && channel_.axes[j].log_axis_nr == nr)
          return LinkMember{false, static_cast<int>(j)};
    }
    return fail(ErrorId::AxLinkUnknownAxis,
                fmt::format("logical axis number {} is no path axis or spindle of this channel", token));
  }
  if (iequal(token, channel_.main_spindle_name) && main_spindle_ >= 0) return LinkMember{true, main_spindle_, true};
  for (std::size_t i = 0; i < channel_.spindles.size(); ++i)
    if (iequal(token, channel_.spindles[i].name)) return LinkMember{true, static_cast<int>(i)};
  for (std::size_t j = 0; j < n_axes; ++j)
    if (iequal(token, channel_.axes[j].name)) return LinkMember{false, static_cast<int>(j)};
  return fail(ErrorId::AxLinkUnknownAxis, fmt::format("{} is no path axis or spindle of this channel", token));
}

std::expected<void, Diagnostic> AxLinkGroups::check_pair(const nc::AxLinkPair& p, const LinkPairDef& d) const {
  if (d.slave.spindle != d.master.spindle)
    return fail(ErrorId::AxLinkMixedPair,
                     fmt::format("pair {}={}: {} is a {}, {} a {}; a pair couples two path axes or two spindles",
                                 p.slave, p.master, p.slave, d.slave.spindle ? "spindle" : "path axis", p.master,
                                 d.master.spindle ? "spindle" : "path axis"));
  if (same(d.slave, d.master))
    return fail(ErrorId::AxLinkUnknownAxis, fmt::format("pair {}={} couples a spindle or axis with itself", p.slave, p.master));
  if (d.slave.spindle && (p.gantry || p.numerator))
    return fail(ErrorId::AxLinkGantryLimits,
                     fmt::format("pair {}={}: spindles are coupled 1:1, without gantry or scaling", p.slave, p.master));
  if (d.gantry && (d.limit1_mm < 0 || d.limit2_mm < d.limit1_mm))
    return fail(ErrorId::AxLinkGantryLimits,
                     fmt::format("gantry pair {}={}: limits {} and {} mm", p.slave, p.master, d.limit1_mm, d.limit2_mm));
  return {};
}

std::expected<void, Diagnostic> AxLinkGroups::define(const nc::SetAxLink& s) {
  if (s.group < 1 || s.group > kernel::kMaxLinkGroupNr)
    return fail(ErrorId::AxLinkGroupRange,
                fmt::format("coupling group {}: the program defines groups 1..{}", s.group, kernel::kMaxLinkGroupNr));
  if (s.pairs.size() > kernel::kMaxLinkPairs)
    return fail(ErrorId::AxLinkGroupRange,
                fmt::format("coupling group {} has {} pairs, at most {}", s.group, s.pairs.size(), kernel::kMaxLinkPairs));
  LinkGroupDef& g = groups_[static_cast<std::size_t>(s.group)];
  if (g.enabled)
    return fail(ErrorId::AxLinkGroupEnabled, fmt::format("coupling group {} is enabled and cannot be changed", s.group));
  LinkGroupDef def;
  def.main_spindle = main_spindle_;
  for (const nc::AxLinkPair& p : s.pairs) {
    LinkPairDef d;
    auto slave = resolve(p.slave, s.by_number);
    if (!slave) return std::unexpected(slave.error());
    auto master = resolve(p.master, s.by_number);
    if (!master) return std::unexpected(master.error());
    d.slave = *slave;
    d.master = *master;
    d.gantry = p.gantry;
    d.limit1_mm = p.limit1_mm.value_or(0);
    d.limit2_mm = p.limit2_mm.value_or(0);
    if (p.numerator && p.denominator) d.ratio = *p.numerator / *p.denominator;
    if (auto r = check_pair(p, d); !r) return r;
    for (const LinkPairDef& o : def.pairs)
      if (same(o.slave, d.slave))
        return fail(ErrorId::AxLinkSlaveTwice, fmt::format("{} is the slave of two pairs in group {}", p.slave, s.group));
    def.pairs.push_back(d);
  }
  g = std::move(def);
  return {};
}

// A member of group g against the groups enabled now (21283..21285).
std::expected<void, Diagnostic> AxLinkGroups::check_against_enabled(int group) const {
  for (int other : enable_order_) {
    for (const LinkPairDef& p : groups_[static_cast<std::size_t>(group)].pairs) {
      for (const LinkPairDef& q : groups_[static_cast<std::size_t>(other)].pairs) {
        const std::string name = member_name(p.slave);
        if (same(p.slave, q.slave))
          return fail(ErrorId::AxLinkSlaveAlreadySlave, fmt::format("{} is already the slave of enabled group {}", name, other));
        if (same(p.slave, q.master))
          return fail(ErrorId::AxLinkSlaveIsMaster, fmt::format("{} is the master of enabled group {}", name, other));
        if (same(p.master, q.slave))
          return fail(ErrorId::AxLinkMasterIsSlave,
                           fmt::format("{} is the slave of enabled group {}", member_name(p.master), other));
      }
    }
  }
  return {};
}

std::expected<const LinkGroupDef*, Diagnostic> AxLinkGroups::enable(std::optional<int> group) {
  const int g = group.value_or(0);
  if (g < 0 || g > kernel::kMaxLinkGroupNr)
    return fail(ErrorId::AxLinkGroupRange, fmt::format("coupling group {}: groups are 0..{}", g, kernel::kMaxLinkGroupNr));
  LinkGroupDef& def = groups_[static_cast<std::size_t>(g)];
  if (def.pairs.empty())
    return fail(ErrorId::AxLinkGroupUndefined,
                g == 0 ? std::string("coupling group 0 has no pairs in the channel list (synchro_data.koppel_gruppe[0])")
                       : fmt::format("coupling group {} is not defined", g));
  if (def.enabled) return fail(ErrorId::AxLinkGroupEnabled, fmt::format("coupling group {} is already enabled", g));
  for (const LinkPairDef& p : def.pairs)
    if ((p.slave.via_main_name || p.master.via_main_name) && def.main_spindle != main_spindle_)
      return fail(ErrorId::AxLinkNamesChanged,
                  fmt::format("group {} was defined with {} = {}; #MAIN SPINDLE has made it {} since",
                              g, channel_.main_spindle_name,
                              channel_.spindles[static_cast<std::size_t>(def.main_spindle)].name,
                              channel_.spindles[static_cast<std::size_t>(main_spindle_)].name));
  for (const LinkPairDef& p : def.pairs)
    if (!p.slave.spindle && p.slave.index < 3)
      return fail(ErrorId::AxLinkSlaveIsMainAxis, fmt::format("{} is a main axis of the channel", member_name(p.slave)));
  if (auto r = check_against_enabled(g); !r) return std::unexpected(r.error());
  def.enabled = true;
  enable_order_.push_back(g);
  return &def;
}

std::expected<std::uint32_t, Diagnostic> AxLinkGroups::disable(const nc::DisableAxLink& d) {
  if (d.all) return disable_all();
  if (!d.group) {  // the group enabled last; nothing enabled: nothing to do
    if (enable_order_.empty()) return 0u;
    const int g = enable_order_.back();
    groups_[static_cast<std::size_t>(g)].enabled = false;
    enable_order_.pop_back();
    return 1u << g;
  }
  const int g = *d.group;
  if (g < 0 || g > kernel::kMaxLinkGroupNr || !groups_[static_cast<std::size_t>(g)].enabled)
    return fail(ErrorId::AxLinkNotEnabled, fmt::format("coupling group {} is not enabled", g));
  groups_[static_cast<std::size_t>(g)].enabled = false;
  std::erase(enable_order_, g);
  return 1u << g;
}

std::uint32_t AxLinkGroups::disable_all() {
  std::uint32_t mask = 0;
  for (int g : enable_order_) {
    groups_[static_cast<std::size_t>(g)].enabled = false;
    mask |= 1u << g;
  }
  enable_order_.clear();
  return mask;
}

std::expected<void, Diagnostic> AxLinkGroups::change_main_spindle(int spindle) {
  for (int g : enable_order_)
    for (const LinkPairDef& p : groups_[static_cast<std::size_t>(g)].pairs)
      if ((p.slave.spindle && p.slave.index == spindle) || (p.master.spindle && p.master.index == spindle))
        return fail(ErrorId::AxLinkMainSpindleLinked,
                    fmt::format("{} is coupled in enabled group {}", channel_.spindles[static_cast<std::size_t>(spindle)].name, g));
  main_spindle_ = spindle;
  return {};
}

bool AxLinkGroups::spindle_is_slave(int spindle) const {
  for (int g : enable_order_)
    for (const LinkPairDef& p : groups_[static_cast<std::size_t>(g)].pairs)
      if (p.slave.spindle && p.slave.index == spindle) return true;
  return false;
}

bool AxLinkGroups::axis_is_slave(int axis) const {
  for (int g : enable_order_)
    for (const LinkPairDef& p : groups_[static_cast<std::size_t>(g)].pairs)
      if (!p.slave.spindle && p.slave.index == axis) return true;
  return false;
}

std::vector<int> AxLinkGroups::slaves_of_spindle(int master) const {
  std::vector<int> out;
  for (int g : enable_order_)
    for (const LinkPairDef& p : groups_[static_cast<std::size_t>(g)].pairs)
      if (p.master.spindle && p.master.index == master) out.push_back(p.slave.index);
  return out;
}

std::vector<const LinkPairDef*> AxLinkGroups::axis_pairs() const {
  std::vector<const LinkPairDef*> out;
  for (int g : enable_order_)
    for (const LinkPairDef& p : groups_[static_cast<std::size_t>(g)].pairs)
      if (!p.slave.spindle) out.push_back(&p);
  return out;
}

}  // namespace nck::prep
