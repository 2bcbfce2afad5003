// Plausibility checks across lists (docs/errors.md, 9100xx): axis lists against the
// channels' use of logical axis numbers, offsets against channel axes.
#include <cctype>
#include <fmt/format.h>
#include <map>
#include <set>

#include "build.hpp"
#include "nck/config/drive_feedback.hpp"

namespace nck::config::detail {
namespace {

void check_axis_numbers(const Machine& m, const std::vector<ParamList>& axis_lists, Diagnostics& d) {
  std::map<std::uint32_t, std::size_t> first;
  for (std::size_t i = 0; i < m.axes.size(); ++i) {
    auto nr = m.axes[i].log_axis_nr;
    auto [it, fresh] = first.emplace(nr, i);
    if (!fresh)
      d.add(ErrorId::ConfigAxisNrDuplicate, axis_lists[i].loc("kopf.achs_nr"),
            fmt::format("kopf.achs_nr {} is also used by {}", nr, m.axes[it->second].source.file));
  }
}

int axis_index_of(const Machine& m, std::uint32_t nr) {
  for (std::size_t i = 0; i < m.axes.size(); ++i)
    if (m.axes[i].log_axis_nr == nr) return static_cast<int>(i);
  return -1;
}

// Links channel entries to axis lists and checks that the kinds fit.
void link_channel(Machine& m, ChannelConfig& c, const ParamList& l, Diagnostics& d) {
  for (std::size_t j = 0; j < c.axes.size(); ++j) {
    auto& ax = c.axes[j];
    if (ax.log_axis_nr == 0) continue;
    ax.axis_index = axis_index_of(m, ax.log_axis_nr);
    auto where = l.loc(fmt::format("gruppe[0].achse[{}].log_achs_nr", j));
    if (ax.axis_index < 0)
      d.add(ErrorId::ConfigNoAxisList, where,
            fmt::format("axis {} (logical number {}) has no axis list in startup.lis", ax.name, ax.log_axis_nr));
    else if (m.axes[static_cast<std::size_t>(ax.axis_index)].is_spindle())
      d.add(ErrorId::ConfigAxisKindMismatch, where,
            fmt::format("path axis {} uses axis list {} of type spindle", ax.name,
                        m.axes[static_cast<std::size_t>(ax.axis_index)].source.file));
  }
  for (std::size_t i = 0; i < c.spindles.size(); ++i) {
    auto& s = c.spindles[i];
    if (s.log_axis_nr == 0) continue;
    s.axis_index = axis_index_of(m, s.log_axis_nr);
    auto where = l.loc(fmt::format("spindel[{}].log_achs_nr", i));
    if (s.axis_index < 0) {
      if (!s.plc_control)  // a channel-interface PLC spindle needs no axis list
        d.add(ErrorId::ConfigNoAxisList, where,
              fmt::format("spindle {} (logical number {}) has no axis list; add one or set spindel[{}].plc_control 1",
                          s.name, s.log_axis_nr, i));
    } else if (!m.axes[static_cast<std::size_t>(s.axis_index)].is_spindle()) {
      d.add(ErrorId::ConfigAxisKindMismatch, where,
            fmt::format("spindle {} uses axis list {} whose kenngr.achs_typ is not ACHSTYP_SPINDEL", s.name,
                        m.axes[static_cast<std::size_t>(s.axis_index)].source.file));
    }
  }
}

// A path axis belongs to one channel; a spindle may be known to several.
void check_across_channels(const Machine& m, const std::vector<ChannelLists>& lists, Diagnostics& d) {
  std::map<std::uint32_t, std::uint32_t> path_owner;
  for (const auto& c : m.channels)
    for (const auto& a : c.axes) path_owner.emplace(a.log_axis_nr, c.number);
  for (std::size_t n = 0; n < m.channels.size(); ++n) {
    const auto& c = m.channels[n];
    const auto& l = lists[n].channel;
    for (std::size_t j = 0; j < c.axes.size(); ++j) {
      auto owner = path_owner[c.axes[j].log_axis_nr];
      if (owner != c.number && c.axes[j].log_axis_nr != 0)
        d.add(ErrorId::ConfigAxisNrDuplicate, l.loc(fmt::format("gruppe[0].achse[{}].log_achs_nr", j)),
              fmt::format("path axis number {} already belongs to channel {}", c.axes[j].log_axis_nr, owner));
    }
    for (std::size_t i = 0; i < c.spindles.size(); ++i) {
      auto it = path_owner.find(c.spindles[i].log_axis_nr);
      if (it != path_owner.end() && it->second != c.number)
        d.add(ErrorId::ConfigAxisNrPathAndSpindle, l.loc(fmt::format("spindel[{}].log_achs_nr", i)),
              fmt::format("logical axis number {} is a path axis of channel {}", it->first, it->second));
    }
  }
}

void check_axis_columns(const ParamList& l, std::string_view prefix, std::size_t axes, Diagnostics& d) {
  for (const auto& [key, v] : l.values()) {
    if (!key.starts_with(prefix)) continue;
    std::size_t j = v.index[1];
    if (key.find("achse[") == std::string::npos && key.find("ax_versatz[") == std::string::npos) continue;
    if (j >= axes)
      d.add(ErrorId::ConfigUnusedAxisIndex, v.loc,
            fmt::format("'{}' names channel axis {}, but the channel has {} path axes", key, j, axes));
  }
}

}  // namespace

void cross_check(const ParamList& l, std::string_view a, std::string_view b, bool ok, std::string message,
                 Diagnostics& d) {
  if (ok) return;
  const ParamValue* va = l.find(a);
  const ParamValue* vb = l.find(b);
  if (!va && !vb) return;
  const ParamValue* at = !va ? vb : !vb ? va : (va->loc.line >= vb->loc.line ? va : vb);
  d.add(ErrorId::ConfigCrossRange, at->loc, std::move(message));
}

std::string listed(const ParamList& l, std::string_view key, double internal, std::size_t unit_part) {
  const ParamValue* v = l.find(key);
  std::string pattern;  // "getriebe[0].vb_max" -> "getriebe[].vb_max"
  for (std::size_t i = 0; i < key.size(); ++i) {
    pattern += key[i];
    if (key[i] == '[')
      while (i + 1 < key.size() && key[i + 1] != ']') ++i;
  }
  const ParamInfo* info = v ? v->info : find_parameter(l.kind(), pattern);
  if (!info || info->scale == 0) return fmt::format("{} ({})", key, internal);
  std::string_view unit = info->list_unit;
  for (std::size_t part = 0; part < unit_part; ++part) {
    const std::size_t dot = unit.find(" · ");
    if (dot == std::string_view::npos) break;
    unit.remove_prefix(dot + std::string_view(" · ").size());
  }
  unit = unit.substr(0, unit.find(" · "));
  const double raw = v ? v->raw : internal / info->scale;
  if (unit.empty()) return fmt::format("{} ({})", key, raw);
  // "0.001°/s" is a unit with a factor: 5000 of them, not "5000 0.001°/s".
  const bool factor = std::isdigit(static_cast<unsigned char>(unit.front())) != 0;
  return fmt::format("{} ({}{}{})", key, raw, factor ? " × " : " ", unit);
}

bool check_no_gaps(const std::vector<std::uint32_t>& indices, SourceLoc where, std::string_view what,
                   Diagnostics& d) {
  for (std::size_t n = 0; n < indices.size(); ++n) {
    if (indices[n] == n) continue;
    d.add(ErrorId::ConfigAxisGap, std::move(where),
          fmt::format("{} entries must be numbered 0, 1, 2 ... without gaps; index {} is missing", what, n));
    return false;
  }
  return true;
}

void check_capabilities(const Machine& m, const std::vector<ParamList>& axis_lists, Diagnostics& d) {
  std::set<int> reported;  // a spindle known to two channels: once
  for (const ChannelConfig& c : m.channels)
    for (const ChannelSpindle& s : c.spindles) {
      if (s.axis_index < 0 || s.plc_control || !reported.insert(s.axis_index).second) continue;
      const auto axis = static_cast<std::size_t>(s.axis_index);
      if (!m.axes[axis].is_spindle() || knows_position(m.axes[axis])) continue;
      const ParamList& l = axis_lists[axis];
      // A warning here, the run's error 70252 where a program asks (docs/decisions.md).
      d.add(Diagnostic{ErrorId::SpindleSensorlessPositioning, Severity::warning, l.loc("antr.operation_mode"),
                       fmt::format("spindle {} of channel {} is speed-controlled without position feedback "
                                   "(antr.operation_mode {}): it cannot position (M19) or home (G74), and a "
                                   "program that asks for either stops with error 70252",
                                   s.name, c.number, l.text("antr.operation_mode", "DRIVE_DEFAULT"))});
    }
}

void check_machine(Machine& m, const std::vector<ParamList>& axis_lists,
                   const std::vector<ChannelLists>& channel_lists, Diagnostics& d) {
  check_axis_numbers(m, axis_lists, d);
  for (std::size_t n = 0; n < m.channels.size(); ++n) {
    link_channel(m, m.channels[n], channel_lists[n].channel, d);
    std::size_t axes = m.channels[n].axes.size();
    check_axis_columns(channel_lists[n].zero, "np_grp[", axes, d);
    check_axis_columns(channel_lists[n].clamp, "pzv_grp[", axes, d);
    check_axis_columns(channel_lists[n].tool, "wz[", axes, d);
  }
  check_across_channels(m, channel_lists, d);
}

}  // namespace nck::config::detail
