// A scenario's channel, spindle and axis names resolved against the machine (setup).
#include <algorithm>

#include <fmt/format.h>

#include "nck/sim/scenario.hpp"
#include "scenario_text.hpp"

namespace nck::sim {
namespace {

bool needs_spindle(ActionKind k) {
  switch (k) {
    case ActionKind::spindle_override:
    case ActionKind::override_valid:
    case ActionKind::spindle_feedhold:
    case ActionKind::spindle_reset:
    case ActionKind::spindle_cmd: return true;
    default: return false;
  }
}

// Index of the named spindle in the channel, or plc::kNoSpindle. The exact
// designation wins; otherwise the channel's main-spindle name addresses the
// configured main spindle.
std::int8_t find_spindle(const config::ChannelConfig& ch, std::string_view name) {
  for (std::size_t i = 0; i < ch.spindles.size() && i < config::kMaxSpindles; ++i)
    if (detail::iequals(ch.spindles[i].name, name)) return static_cast<std::int8_t>(i);
  if (!detail::iequals(ch.main_spindle_name, name)) return plc::kNoSpindle;
  for (std::size_t i = 0; i < ch.spindles.size() && i < config::kMaxSpindles; ++i)
    if (ch.spindles[i].log_axis_nr == ch.main_spindle_ax_nr) return static_cast<std::int8_t>(i);
  return plc::kNoSpindle;
}

// false when the action must be dropped.
bool resolve_one(ScenarioAction& a, const config::Machine& m, const plc::SpindleMap& map,
                 const std::string& file, Diagnostics& diags) {
  if (a.channel < 1 || a.channel > m.channels.size()) {
    diags.add(ErrorId::PlcScenarioBadChannel, SourceLoc{file, a.line, 0},
              fmt::format("channel {} does not exist; the machine has {} channel(s)", a.channel,
                          m.channels.size()));
    return false;
  }
  const auto& ch = m.channels[a.channel - 1];
  if (a.kind == ActionKind::handwheel || a.kind == ActionKind::jog || a.kind == ActionKind::jog_increment) {
    const std::string_view name(a.axis_name.data());
    for (std::size_t j = 0; j < ch.axes.size(); ++j)
      if (detail::iequals(ch.axes[j].name, name)) a.axis = static_cast<std::int8_t>(j);
    if (a.axis >= 0) return true;
    diags.add(ErrorId::PlcScenarioUnknownAxis, SourceLoc{file, a.line, 0},
              fmt::format("channel {} has no path axis '{}'", a.channel, name));
    return false;
  }
  if (!a.has_spindle()) return !needs_spindle(a.kind);
  a.spindle = find_spindle(ch, a.spindle_view());
  if (a.spindle == plc::kNoSpindle) {
    std::string known;
    for (const auto& s : ch.spindles) known += (known.empty() ? "" : ", ") + s.name;
    diags.add(ErrorId::PlcScenarioUnknownSpindle, SourceLoc{file, a.line, 0},
              fmt::format("channel {} has no spindle '{}' (it has: {})", a.channel,
                          a.spindle_view(), known.empty() ? "none" : known));
    return false;
  }
  a.hli_spindle = map.at(a.channel, a.spindle);
  a.cmd.spindle = a.spindle;
  a.cmd.channel = a.channel;
  return true;
}

}  // namespace

void resolve_spindles(Scenario& sc, const config::Machine& m, const plc::SpindleMap& map,
                      Diagnostics& diags) {
  const auto unresolved = [&](ScenarioAction& a) { return !resolve_one(a, m, map, sc.file, diags); };
  std::erase_if(sc.actions, unresolved);
  std::erase_if(sc.triggered, unresolved);
}

}  // namespace nck::sim
