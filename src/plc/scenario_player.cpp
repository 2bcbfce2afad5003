// Scenario replay: spindle resolution (setup), due actions and their effect on
// the HLI image (rt).
#include <algorithm>

#include <fmt/format.h>

#include "nck/plc/scenario.hpp"
#include "scenario_text.hpp"

namespace nck::plc {
namespace {

constexpr double kTimeEps_s = 1e-9;  // same rounding guard as the PLC's delays

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

// Index of the named spindle in the channel, or kNoSpindle. The exact
// designation wins; otherwise the channel's main-spindle name addresses the
// configured main spindle.
std::int8_t find_spindle(const config::ChannelConfig& ch, std::string_view name) {
  for (std::size_t i = 0; i < ch.spindles.size() && i < config::kMaxSpindles; ++i)
    if (detail::iequals(ch.spindles[i].name, name)) return static_cast<std::int8_t>(i);
  if (!detail::iequals(ch.main_spindle_name, name)) return kNoSpindle;
  for (std::size_t i = 0; i < ch.spindles.size() && i < config::kMaxSpindles; ++i)
    if (ch.spindles[i].log_axis_nr == ch.main_spindle_ax_nr) return static_cast<std::int8_t>(i);
  return kNoSpindle;
}

// false when the action must be dropped.
bool resolve_one(ScenarioAction& a, const config::Machine& m, const SpindleMap& map,
                 const std::string& file, Diagnostics& diags) {
  if (a.channel < 1 || a.channel > m.channels.size()) {
    diags.add(ErrorId::PlcScenarioBadChannel, SourceLoc{file, a.line, 0},
              fmt::format("channel {} does not exist; the machine has {} channel(s)", a.channel,
                          m.channels.size()));
    return false;
  }
  const auto& ch = m.channels[a.channel - 1];
  if (a.kind == ActionKind::handwheel) {
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
  if (a.spindle == kNoSpindle) {
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

void resolve_spindles(Scenario& sc, const config::Machine& m, const SpindleMap& map,
                      Diagnostics& diags) {
  std::erase_if(sc.actions, [&](ScenarioAction& a) { return !resolve_one(a, m, map, sc.file, diags); });
}

std::span<const ScenarioAction> ScenarioPlayer::due(double now_s) noexcept {
  const std::size_t first = next_;
  while (next_ < actions_.size() && actions_[next_].t_s <= now_s + kTimeEps_s) ++next_;
  return actions_.subspan(first, next_ - first);
}

namespace {

SpindleControl* control_of(const ScenarioAction& a, HliImage& hli) noexcept {
  if (a.hli_spindle < 0 || static_cast<std::size_t>(a.hli_spindle) >= kMaxHliSpindles) return nullptr;
  return &hli.spindle_control[static_cast<std::size_t>(a.hli_spindle)];
}

ApplyResult apply_spindle(const ScenarioAction& a, SpindleControl* sc) noexcept {
  if (sc == nullptr) return ApplyResult::no_spindle;
  switch (a.kind) {
    case ActionKind::spindle_override: sc->override_percent = a.value; sc->override_valid = true; break;
    case ActionKind::override_valid: sc->override_valid = a.on; break;
    case ActionKind::spindle_feedhold: sc->feedhold = a.on; break;
    case ActionKind::spindle_stop_at_end: sc->stop_at_program_end = a.on; break;
    case ActionKind::spindle_reset: sc->reset = true; break;
    default: break;
  }
  return ApplyResult::ok;
}

// spindle_stop_at_end without a spindle: every spindle of the channel.
void stop_at_end_all(const ScenarioAction& a, const SpindleMap& map, HliImage& hli) noexcept {
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(config::kMaxSpindles); ++i) {
    const std::int8_t h = map.at(a.channel, i);
    if (h >= 0 && static_cast<std::size_t>(h) < kMaxHliSpindles)
      hli.spindle_control[static_cast<std::size_t>(h)].stop_at_program_end = a.on;
  }
}

}  // namespace

ApplyResult apply(const ScenarioAction& a, const SpindleMap& map, HliImage& hli, PlcSim& plc,
                  ExtCommandQueue& ext) noexcept {
  const std::size_t c = a.channel >= 1 && a.channel <= kMaxHliChannels ? a.channel - 1u : 0u;
  ChannelControl& ch = hli.channel[c];
  switch (a.kind) {
    case ActionKind::feed_override: ch.feed_override_percent = a.value; return ApplyResult::ok;
    case ActionKind::feedhold: ch.feedhold = a.on; return ApplyResult::ok;
    case ActionKind::reset: ch.reset = true; return ApplyResult::ok;
    case ActionKind::optional_stop: ch.optional_stop = a.on; return ApplyResult::ok;
    case ActionKind::silent: plc.set_silent(a.on); return ApplyResult::ok;
    case ActionKind::handwheel: return ApplyResult::ok;  // the kernel moves the axis
    case ActionKind::spindle_cmd:
      if (a.spindle == kNoSpindle) return ApplyResult::no_spindle;
      return ext.push(a.cmd) != 0 ? ApplyResult::ok : ApplyResult::ext_queue_full;
    case ActionKind::spindle_stop_at_end:
      if (!a.has_spindle()) {
        stop_at_end_all(a, map, hli);
        return ApplyResult::ok;
      }
      return apply_spindle(a, control_of(a, hli));
    default:
      return apply_spindle(a, control_of(a, hli));
  }
}

}  // namespace nck::plc
