// A scenario's channel, spindle and axis names resolved against the machine (setup).
#include <algorithm>
#include <type_traits>

#include <fmt/format.h>

#include "nck/sim/scenario.hpp"
#include "scenario_text.hpp"

namespace nck::sim {
namespace {

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

std::int8_t find_axis(const config::ChannelConfig& ch, std::string_view name) {
  for (std::size_t j = 0; j < ch.axes.size(); ++j)
    if (detail::iequals(ch.axes[j].name, name)) return static_cast<std::int8_t>(j);
  return -1;
}

bool resolve_axis(act::AxisRef& axis, const ScenarioAction& a, const config::ChannelConfig& ch,
                  const std::string& file, Diagnostics& diags) {
  axis.index = find_axis(ch, axis.view());
  if (axis.index >= 0) return true;
  diags.add(ErrorId::PlcScenarioUnknownAxis, SourceLoc{file, a.line, 0},
            fmt::format("channel {} has no path axis '{}'", a.channel, axis.view()));
  return false;
}

// An amplifier fault's drive: a path axis's, or a spindle's that has an
// axis list (its drive; a spindle without one has no amplifier the NC knows).
bool resolve_drive(act::AxisRef& axis, const ScenarioAction& a, const config::ChannelConfig& ch,
                   const std::string& file, Diagnostics& diags) {
  const std::int8_t s = find_spindle(ch, axis.view());
  if (find_axis(ch, axis.view()) < 0 && s != plc::kNoSpindle && ch.spindles[static_cast<std::size_t>(s)].axis_index >= 0) {
    axis.spindle_axis_list = static_cast<std::int16_t>(ch.spindles[static_cast<std::size_t>(s)].axis_index);
    return true;
  }
  return resolve_axis(axis, a, ch, file, diags);
}

// A spindle named, or none where the action allows none (spindle_stop_at_end).
bool resolve_spindle(act::SpindleRef& spindle, const ScenarioAction& a, const config::ChannelConfig& ch,
                     const plc::SpindleMap& map, const std::string& file, Diagnostics& diags) {
  if (!spindle.given()) return a.kind() == ActionKind::spindle_stop_at_end;
  spindle.index = find_spindle(ch, spindle.view());
  if (spindle.index == plc::kNoSpindle) {
    std::string known;
    for (const auto& s : ch.spindles) known += (known.empty() ? "" : ", ") + s.name;
    diags.add(ErrorId::PlcScenarioUnknownSpindle, SourceLoc{file, a.line, 0},
              fmt::format("channel {} has no spindle '{}' (it has: {})", a.channel, spindle.view(),
                          known.empty() ? "none" : known));
    return false;
  }
  spindle.hli = map.at(a.channel, spindle.index);
  return true;
}

}  // namespace

bool resolve_action(ScenarioAction& a, const config::Machine& m, const plc::SpindleMap& map,
                    const std::string& file, Diagnostics& diags) {
  if (a.channel < 1 || a.channel > m.channels.size()) {
    diags.add(ErrorId::PlcScenarioBadChannel, SourceLoc{file, a.line, 0},
              fmt::format("channel {} does not exist; the machine has {} channel(s)", a.channel,
                          m.channels.size()));
    return false;
  }
  const config::ChannelConfig& ch = m.channels[a.channel - 1];
  const ScenarioAction& head = a;
  return std::visit(
      [&](auto& p) {
        if constexpr (std::is_same_v<std::decay_t<decltype(p)>, act::AmpFault>) {
          return resolve_drive(p.axis, head, ch, file, diags);
        } else if constexpr (requires { p.axis; }) {
          return resolve_axis(p.axis, head, ch, file, diags);
        } else if constexpr (requires { p.spindle; }) {
          if (!resolve_spindle(p.spindle, head, ch, map, file, diags)) return false;
          if constexpr (requires { p.cmd; }) {
            p.cmd.spindle = p.spindle.index;
            p.cmd.channel = head.channel;
          }
          return true;
        } else {
          return true;
        }
      },
      a.payload);
}

void resolve_spindles(Scenario& sc, const config::Machine& m, const plc::SpindleMap& map,
                      Diagnostics& diags) {
  const plc::SpindleMap& spindles = map;
  const auto unresolved = [&](ScenarioAction& a) { return !resolve_action(a, m, spindles, sc.file, diags); };
  std::erase_if(sc.actions, unresolved);
  std::erase_if(sc.triggered, unresolved);
}

}  // namespace nck::sim
