#include "nck/sim/operator_action.hpp"

#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "nck/sim/action_words.hpp"
#include "nck/plc/hli.hpp"
#include "scenario_text.hpp"

namespace nck::sim {
namespace {

struct Problem {
  ErrorId id;
  std::string message;
};

std::string shown(double v, Quoting q) { return q == Quoting::python ? fmt::format("{:g}", v) : fmt::format("{}", v); }
std::string shown(std::uint32_t mask, Quoting q) {
  return q == Quoting::python ? fmt::format("{:#x}", mask) : fmt::format("{}", mask);
}

// The payload's values as the scenario parser would take its words, in the
// order a line writes them.
std::optional<Problem> value_problem(const ActionPayload& payload, Quoting q) {
  return std::visit(
      [&](const auto& p) -> std::optional<Problem> {
        using T = std::decay_t<decltype(p)>;
        if constexpr (requires { p.spindle; })
          if (p.spindle.given() && !detail::valid_spindle_name(p.spindle.view()))
            return Problem{ErrorId::PlcScenarioBadSpindleName, words::not_a_spindle(detail::printable(p.spindle.view()))};
        if constexpr (requires { p.axis; })
          if (!words::valid_axis_name(p.axis.view()))
            return Problem{ErrorId::PlcScenarioBadNumber, words::not_an_axis(detail::printable(p.axis.view()))};
        if constexpr (requires { p.percent; })
          if (!words::valid_percent(p.percent))
            return Problem{ErrorId::PlcScenarioBadNumber, words::not_a_percent(shown(p.percent, q))};
        if constexpr (std::is_same_v<T, act::SkipMask>)
          if (p.mask > words::kAllSkipLevels)
            return Problem{ErrorId::PlcScenarioBadNumber, words::not_a_skip_mask(shown(p.mask, q))};
        if constexpr (std::is_same_v<T, act::Jog>)
          if (p.direction != 0 && p.speed_mm_min < 0)
            return Problem{ErrorId::PlcScenarioBadJog, words::not_a_jog_speed(shown(p.speed_mm_min, q))};
        if constexpr (std::is_same_v<T, act::JogIncrement>)
          if (!(p.step_mm > 0)) return Problem{ErrorId::PlcScenarioBadJog, words::not_a_jog_step(shown(p.step_mm, q))};
        return std::nullopt;
      },
      payload);
}

std::string_view on_off(bool on) { return on ? "on" : "off"; }

// The words after the action's name in its scenario line.
std::string operator_words(const OperatorAction& op, Quoting q) {
  return std::visit(
      [&](const auto& p) -> std::string {
        using T = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<T, act::SpindleOverride>)
          return fmt::format(" {} {}", p.spindle.view(), shown(p.percent, q));
        else if constexpr (requires { p.percent; }) return " " + shown(p.percent, q);
        else if constexpr (std::is_same_v<T, act::SkipMask>)
          return " " + shown(p.mask, q);
        else if constexpr (std::is_same_v<T, act::Mode>) return p.manual ? " manual" : " automatic";
        else if constexpr (std::is_same_v<T, act::Jog>)
          return fmt::format(" {} {}{}", p.axis.view(), p.direction > 0 ? "+" : p.direction < 0 ? "-" : "stop",
                             p.direction != 0 && p.speed_mm_min > 0 ? " " + shown(p.speed_mm_min, q) : "");
        else if constexpr (std::is_same_v<T, act::JogIncrement>)
          return fmt::format(" {} {} {}", p.axis.view(), p.direction < 0 ? "-" : "+", shown(p.step_mm, q));
        else if constexpr (std::is_same_v<T, act::Mdi>) return " " + op.mdi_text;
        else if constexpr (std::is_same_v<T, act::DriveFault> || std::is_same_v<T, act::AmpFault>)
          return fmt::format(" {} {}", p.axis.view(), on_off(p.on));
        else if constexpr (std::is_same_v<T, act::LimitSwitch>)
          return fmt::format(" {} {} {}", p.axis.view(), p.direction < 0 ? "-" : "+", on_off(p.on));
        else if constexpr (requires { p.spindle; p.on; }) return fmt::format(" {} {}", p.spindle.view(), on_off(p.on));
        else if constexpr (requires { p.on; }) return fmt::format(" {}", on_off(p.on));
        else if constexpr (requires { p.spindle; }) return fmt::format(" {}", p.spindle.view());
        else return "";
      },
      op.action.payload);
}

}  // namespace

std::string operator_line(const OperatorAction& op, Quoting q) {
  if (op.action.kind() == ActionKind::spindle_override) {  // the two surfaces have always written it apart
    if (q == Quoting::python) return fmt::format("override{}", operator_words(op, q));
    return fmt::format("ch={} spindle_override{}", op.action.channel, operator_words(op, q));
  }
  return fmt::format("ch={} {}{}", op.action.channel, action_name(op.action.kind()), operator_words(op, q));
}

std::string operator_action_shown(std::string_view word) { return detail::printable(word); }

// The specific ID, not 960040 with it in the text (issue 47 item 5): a
// client tells the refusals apart by the ID. No location: an action typed
// or sent has no file and line (a placeholder such as "api:1" would look
// like one).
Diagnostic operator_action_refused(std::string_view line, ErrorId id, std::string_view message, const std::string&) {
  return make_diagnostic(id, SourceLoc{}, fmt::format("'{}': {}", detail::printable(line), message));
}

std::optional<OperatorAction> check_operator_action(OperatorAction op, const config::Machine& m, Diagnostics& diags,
                                                    const std::string& source, Quoting q) {
  if (op.action.kind() == ActionKind::block_search) {
    diags.add(ErrorId::PlcOperatorActionNotLive, SourceLoc{},
              "block_search starts a run: it is no action on a running kernel");
    return std::nullopt;
  }
  const auto refuse = [&](ErrorId id, std::string_view message) {
    diags.add(operator_action_refused(operator_line(op, q), id, message, source));
    return std::nullopt;
  };
  if (!words::valid_channel_number(op.action.channel))
    return refuse(ErrorId::PlcScenarioBadChannel, words::not_a_channel(fmt::format("{}", op.action.channel)));
  if (op.action.kind() == ActionKind::mdi && op.mdi_text.empty())
    return refuse(ErrorId::PlcScenarioMissingArgument, fmt::format("missing {}", words::kMissingMdiText));
  if (const auto p = value_problem(op.action.payload, q)) return refuse(p->id, p->message);
  Diagnostics found;
  if (!resolve_action(op.action, m, plc::build_spindle_map(m), source, found))
    return refuse(found.items().front().id, found.items().front().message);
  return op;
}

std::optional<OperatorAction> parse_operator_action(std::string_view line, const config::Machine& m,
                                                    Diagnostics& diags, const std::string& source) {
  const SourceLoc loc{};
  if (line.find('\n') != std::string_view::npos || line.find('\r') != std::string_view::npos) {
    diags.add(ErrorId::PlcOperatorActionBad, loc, "an operator action is one line");
    return std::nullopt;
  }
  // Time 0 in front: the scenario parser then reads the line as written.
  Diagnostics found;
  Scenario sc = parse_scenario(fmt::format("0 {}", line), source, found);
  resolve_spindles(sc, m, plc::build_spindle_map(m), found);
  if (found.has_errors()) {
    for (const Diagnostic& d : found.items()) diags.add(operator_action_refused(line, d.id, d.message, source));
    return std::nullopt;
  }
  if (sc.actions.size() != 1) {
    diags.add(ErrorId::PlcOperatorActionBad, loc, fmt::format("'{}' is no action", detail::printable(line)));
    return std::nullopt;
  }
  OperatorAction op{sc.actions.front(), {}};
  if (op.action.kind() == ActionKind::block_search) {
    diags.add(ErrorId::PlcOperatorActionNotLive, loc, "block_search starts a run: it is no action on a running kernel");
    return std::nullopt;
  }
  if (op.action.kind() == ActionKind::mdi) op.mdi_text = sc.texts.front();
  return op;
}

}  // namespace nck::sim
