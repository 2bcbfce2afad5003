// setup: parsing of --plc scenario files (grammar: docs/plc-scenario.md).
#include <cctype>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>

#include <fmt/format.h>

#include "nck/core/edit_distance.hpp"
#include "nck/sim/operator_action.hpp"
#include "nck/sim/scenario.hpp"
#include "nck/sim/action_words.hpp"
#include "scenario_text.hpp"

namespace nck::sim {
namespace {

using detail::iequals;
using detail::Token;

struct ActionSpelling {
  std::string_view word;
  ActionKind kind;
};

// Every accepted spelling; the first one of a kind is its primary name.
constexpr std::array kActions = {
    ActionSpelling{"override", ActionKind::spindle_override},
    ActionSpelling{"spindle_override", ActionKind::spindle_override},
    ActionSpelling{"override_valid", ActionKind::override_valid},
    ActionSpelling{"feed_override", ActionKind::feed_override},
    ActionSpelling{"rapid_override", ActionKind::rapid_override},
    ActionSpelling{"feedhold", ActionKind::feedhold},
    ActionSpelling{"spindle_feedhold", ActionKind::spindle_feedhold},
    ActionSpelling{"spindle_stop_at_end", ActionKind::spindle_stop_at_end},
    ActionSpelling{"reset", ActionKind::reset},
    ActionSpelling{"spindle_reset", ActionKind::spindle_reset},
    ActionSpelling{"optional_stop", ActionKind::optional_stop},
    ActionSpelling{"silent", ActionKind::silent},
    ActionSpelling{"spindle_cmd", ActionKind::spindle_cmd},
    ActionSpelling{"handwheel", ActionKind::handwheel},
    ActionSpelling{"variable", ActionKind::variable},
    ActionSpelling{"cycle_start", ActionKind::cycle_start},
    ActionSpelling{"auto_cycle_start", ActionKind::auto_cycle_start},
    ActionSpelling{"single_step", ActionKind::single_step},
    ActionSpelling{"skip_mask", ActionKind::skip_mask},
    ActionSpelling{"block_search", ActionKind::block_search},
    ActionSpelling{"mdi", ActionKind::mdi},
    ActionSpelling{"stop", ActionKind::stop},
    ActionSpelling{"jog", ActionKind::jog},
    ActionSpelling{"jog_increment", ActionKind::jog_increment},
    ActionSpelling{"mode", ActionKind::mode},
    ActionSpelling{"drive_fault", ActionKind::drive_fault},
    ActionSpelling{"estop", ActionKind::estop},
    ActionSpelling{"machine_on", ActionKind::machine_on},
    ActionSpelling{"amp_fault", ActionKind::amp_fault},
    ActionSpelling{"limit_switch", ActionKind::limit_switch},
};

// Parses one line; reports its first problem and returns nothing then.
class LineParser {
 public:
  LineParser(std::span<const Token> toks, const std::string& file, std::uint32_t line,
             Diagnostics& diags)
      : toks_(toks), file_(file), line_(line), diags_(diags) {}

  std::optional<ScenarioAction> parse();
  // mdi: the NC text, as written from its first word to its last.
  const std::string& mdi_text() const { return mdi_text_; }

 private:
  bool fail(ErrorId id, std::uint32_t column, std::string msg) {
    diags_.add(id, SourceLoc{file_, line_, column}, std::move(msg));
    return false;
  }
  // Column just after the last token, for "missing argument" reports.
  std::uint32_t end_column() const {
    const Token& t = toks_.back();
    return t.column + static_cast<std::uint32_t>(t.text.size());
  }
  bool at_end() const { return next_ >= toks_.size(); }
  bool parse_time(ScenarioAction& a);
  bool parse_channel(ScenarioAction& a);
  bool parse_action(ScenarioAction& a);
  bool parse_args(ScenarioAction& a);
  bool need(std::string_view what);
  bool take_spindle(act::SpindleRef& spindle);
  bool take_switch(bool& on);
  bool take_percent(double& pct);
  bool take_spindle_cmd(std::uint8_t channel, act::SpindleCmd& c);
  bool take_handwheel(act::Handwheel& h);
  bool take_axis(act::AxisRef& axis);
  bool take_jog(act::Jog& j);
  bool take_jog_increment(act::JogIncrement& j);
  bool take_jog_direction(std::int8_t& direction, bool stop_allowed);
  bool take_mode(act::Mode& m);
  bool take_variable(act::Variable& v);
  bool take_skip_mask(std::uint32_t& mask);
  bool take_block_search(const ScenarioAction& a, act::BlockSearch& b);
  bool take_mdi_text();
  bool take_search_mark(act::BlockSearch& b);
  bool take_whole(std::string_view what, std::int64_t lowest, std::int64_t& value);
  bool take_keyword_value(std::string_view key, double& value, bool& seen);

  std::span<const Token> toks_;
  const std::string& file_;
  std::uint32_t line_;
  Diagnostics& diags_;
  std::size_t next_ = 0;
  std::string mdi_text_;
};

std::optional<ScenarioAction> LineParser::parse() {
  ScenarioAction a;
  a.line = line_;
  if (!parse_time(a) || !parse_channel(a) || !parse_action(a) || !parse_args(a)) return {};
  if (!at_end()) {
    fail(ErrorId::PlcScenarioExtraArgument, toks_[next_].column,
         fmt::format("'{}' is one word too many for '{}'; remove it or start a comment with #",
                     detail::printable(toks_[next_].text), action_name(a.kind())));
    return {};
  }
  return a;
}

// '@STATE[+DELAY]': the first time the channel enters that program state.
std::optional<kernel::ProgramState> trigger_state(std::string_view name) {
  using S = kernel::ProgramState;
  for (S s : {S::idle, S::running, S::hold, S::searching, S::returning, S::error, S::ended})
    if (iequals(name, kernel::state_name(s))) return s;
  return std::nullopt;
}

bool LineParser::parse_time(ScenarioAction& a) {
  const Token& t = toks_[next_++];
  if (!t.text.empty() && t.text[0] == '@') {
    const std::string_view rest = t.text.substr(1);
    const std::size_t plus = rest.find('+');
    a.trigger = trigger_state(rest.substr(0, plus));
    const auto delay = plus == std::string_view::npos ? std::optional<double>(0.0) : detail::to_number(rest.substr(plus + 1));
    if (!a.trigger || !delay || *delay < 0)
      return fail(ErrorId::PlcScenarioBadTime, t.column,
                  fmt::format("'{}' is no trigger; write @STATE or @STATE+SECONDS with a program state "
                              "(idle, running, hold, searching, returning, error, ended), e.g. '@hold cycle_start'",
                              detail::printable(t.text)));
    a.t_s = *delay;
    return true;
  }
  auto v = detail::to_number(t.text);
  if (!v || *v < 0)
    return fail(ErrorId::PlcScenarioBadTime, t.column,
                fmt::format("'{}' is not a time; a line starts with the time in seconds (>= 0), "
                            "e.g. '0.5 feed_override 80'",
                            detail::printable(t.text)));
  a.t_s = *v;
  return true;
}

bool LineParser::parse_channel(ScenarioAction& a) {
  if (at_end()) return true;
  const Token& t = toks_[next_];
  std::string_view num_text;
  std::uint32_t column = t.column;
  if (t.text.size() > 3 && iequals(t.text.substr(0, 3), "ch=")) {
    num_text = t.text.substr(3);
    ++next_;
  } else if (iequals(t.text, "channel")) {
    ++next_;
    if (!need("a channel number after 'channel'")) return false;
    num_text = toks_[next_].text;
    column = toks_[next_++].column;
  } else {
    return true;  // no channel prefix: channel 1
  }
  auto v = detail::to_number(num_text);
  if (!v || !words::valid_channel_number(*v))
    return fail(ErrorId::PlcScenarioBadChannel, column, words::not_a_channel(detail::printable(num_text)));
  a.channel = static_cast<std::uint8_t>(*v);
  return true;
}

bool LineParser::parse_action(ScenarioAction& a) {
  if (!need("an action after the time (e.g. feed_override 80)")) return false;
  const Token& t = toks_[next_++];
  for (const auto& s : kActions) {
    if (iequals(t.text, s.word)) {
      a.payload = payload_of(s.kind);
      return true;
    }
  }
  std::string_view nearest = kActions[0].word;
  std::size_t best = SIZE_MAX;
  for (const auto& s : kActions) {
    std::size_t d = edit_distance(t.text, s.word, best);
    if (d < best) best = d, nearest = s.word;
  }
  return fail(ErrorId::PlcScenarioUnknownAction, t.column,
              fmt::format("unknown action '{}'; did you mean '{}'?", detail::printable(t.text),
                          nearest));
}

bool LineParser::need(std::string_view what) {
  if (!at_end()) return true;
  return fail(ErrorId::PlcScenarioMissingArgument, end_column(),
              fmt::format("missing {}", what));
}

// The payload parse_action chose, filled in from the line's words.
bool LineParser::parse_args(ScenarioAction& a) {
  return std::visit(
      [&](auto& p) {
        using T = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<T, act::SpindleOverride>) return take_spindle(p.spindle) && take_percent(p.percent);
        else if constexpr (std::is_same_v<T, act::FeedOverride> || std::is_same_v<T, act::RapidOverride>)
          return take_percent(p.percent);
        else if constexpr (std::is_same_v<T, act::OverrideValid> || std::is_same_v<T, act::SpindleFeedhold>)
          return take_spindle(p.spindle) && take_switch(p.on);
        else if constexpr (std::is_same_v<T, act::SpindleStopAtEnd>)
          return take_switch(p.on) && (at_end() || take_spindle(p.spindle));  // optional spindle
        else if constexpr (std::is_same_v<T, act::Feedhold> || std::is_same_v<T, act::OptionalStop> ||
                           std::is_same_v<T, act::Silent> || std::is_same_v<T, act::AutoCycleStart> ||
                           std::is_same_v<T, act::SingleStep> || std::is_same_v<T, act::Estop> ||
                           std::is_same_v<T, act::MachineOn>)
          return take_switch(p.on);
        else if constexpr (std::is_same_v<T, act::SpindleReset>) return take_spindle(p.spindle);
        else if constexpr (std::is_same_v<T, act::SpindleCmd>)
          return take_spindle(p.spindle) && take_spindle_cmd(a.channel, p);
        else if constexpr (std::is_same_v<T, act::Handwheel>) return take_handwheel(p);
        else if constexpr (std::is_same_v<T, act::Variable>) return take_variable(p);
        else if constexpr (std::is_same_v<T, act::SkipMask>) return take_skip_mask(p.mask);
        else if constexpr (std::is_same_v<T, act::BlockSearch>) return take_block_search(a, p);
        else if constexpr (std::is_same_v<T, act::Mdi>) return take_mdi_text();
        else if constexpr (std::is_same_v<T, act::Jog>) return take_jog(p);
        else if constexpr (std::is_same_v<T, act::JogIncrement>) return take_jog_increment(p);
        else if constexpr (std::is_same_v<T, act::Mode>) return take_mode(p);
        else if constexpr (std::is_same_v<T, act::DriveFault> || std::is_same_v<T, act::AmpFault>)
          return take_axis(p.axis) && take_switch(p.on);
        else if constexpr (std::is_same_v<T, act::LimitSwitch>)
          return take_axis(p.axis) && take_jog_direction(p.direction, false) && take_switch(p.on);
        else return true;  // reset, stop, cycle_start: no arguments
      },
      a.payload);
}

// A path axis name as the channel knows it (checked against the machine later).
bool LineParser::take_axis(act::AxisRef& axis) {
  if (!need("the axis name (e.g. X)")) return false;
  const Token& t = toks_[next_++];
  if (!words::valid_axis_name(t.text))
    return fail(ErrorId::PlcScenarioBadNumber, t.column, words::not_an_axis(detail::printable(t.text)));
  words::copy_name(t.text, axis.name);
  return true;
}

// handwheel <axis> <mm>: the axis name as the channel knows it, the distance signed.
bool LineParser::take_handwheel(act::Handwheel& h) {
  if (!take_axis(h.axis)) return false;
  if (!need("the handwheel distance in mm")) return false;
  const Token& t = toks_[next_++];
  auto v = detail::to_number(t.text);
  if (!v)
    return fail(ErrorId::PlcScenarioBadNumber, t.column,
                fmt::format("'{}' is not a distance; write mm, e.g. 0.5", detail::printable(t.text)));
  h.distance_mm = *v;
  return true;
}

// + or - (or stop, where allowed): the jog's direction.
bool LineParser::take_jog_direction(std::int8_t& direction, bool stop_allowed) {
  if (!need(stop_allowed ? "+, - or stop" : "+ or -")) return false;
  const Token& t = toks_[next_++];
  const std::optional<std::int8_t> d = jog_direction_word(t.text, stop_allowed);
  if (!d)
    return fail(ErrorId::PlcScenarioBadJog, t.column, words::not_a_jog_direction(detail::printable(t.text), stop_allowed));
  direction = *d;
  return true;
}

// jog <axis> +|- [speed mm/min] | jog <axis> stop: a continuous jog starts
// (until its stop line) or is released.
bool LineParser::take_jog(act::Jog& j) {
  if (!take_axis(j.axis) || !take_jog_direction(j.direction, true)) return false;
  if (at_end() || j.direction == 0) return true;
  const Token& t = toks_[next_++];
  auto v = detail::to_number(t.text);
  if (!v || *v <= 0) return fail(ErrorId::PlcScenarioBadJog, t.column, words::not_a_jog_speed(detail::printable(t.text)));
  j.speed_mm_min = *v;
  return true;
}

// jog_increment <axis> +|- <step mm>: one step per line.
bool LineParser::take_jog_increment(act::JogIncrement& j) {
  if (!take_axis(j.axis) || !take_jog_direction(j.direction, false)) return false;
  if (!need("the step in mm (e.g. 0.1)")) return false;
  const Token& t = toks_[next_++];
  auto v = detail::to_number(t.text);
  if (!v || *v <= 0) return fail(ErrorId::PlcScenarioBadJog, t.column, words::not_a_jog_step(detail::printable(t.text)));
  j.step_mm = *v;
  return true;
}

// mode manual|automatic.
bool LineParser::take_mode(act::Mode& m) {
  if (!need("manual or automatic")) return false;
  const Token& t = toks_[next_++];
  const std::optional<bool> manual = manual_mode_word(t.text);
  if (!manual) return fail(ErrorId::PlcScenarioBadMode, t.column, words::not_a_mode(detail::printable(t.text)));
  m.manual = *manual;
  return true;
}

// variable <name> <value>: a channel variable (e.g. the distance sensor's
// value for SENSOR_SOURCE=VARIABLE), matched by name, case-insensitively.
bool LineParser::take_variable(act::Variable& var) {
  if (!need("the variable name (e.g. V.E.GAP)")) return false;
  const Token& name = toks_[next_++];
  if (name.text.empty() || name.text.size() >= var.name.size())
    return fail(ErrorId::PlcScenarioBadNumber, name.column,
                fmt::format("'{}' is not a variable name (1 to {} characters)", detail::printable(name.text),
                            var.name.size() - 1));
  for (std::size_t i = 0; i < name.text.size(); ++i)
    var.name[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(name.text[i])));
  if (!need("the variable's value")) return false;
  const Token& t = toks_[next_++];
  auto v = detail::to_number(t.text);
  if (!v)
    return fail(ErrorId::PlcScenarioBadNumber, t.column,
                fmt::format("'{}' is not a number", detail::printable(t.text)));
  var.value = *v;
  return true;
}

bool LineParser::take_spindle(act::SpindleRef& spindle) {
  if (!need("the spindle name (e.g. S1)")) return false;
  const Token& t = toks_[next_++];
  if (!detail::valid_spindle_name(t.text))
    return fail(ErrorId::PlcScenarioBadSpindleName, t.column, words::not_a_spindle(detail::printable(t.text)));
  words::copy_name(t.text, spindle.name);
  return true;
}

bool LineParser::take_switch(bool& on) {
  if (!need("on or off")) return false;
  const Token& t = toks_[next_++];
  if (iequals(t.text, "on") || t.text == "1") {
    on = true;
    return true;
  }
  if (iequals(t.text, "off") || t.text == "0") {
    on = false;
    return true;
  }
  return fail(ErrorId::PlcScenarioBadSwitch, t.column,
              fmt::format("'{}' is not a switch; write on or off", detail::printable(t.text)));
}

bool LineParser::take_percent(double& pct) {
  if (!need("the percentage (0..200)")) return false;
  const Token& t = toks_[next_++];
  auto v = detail::to_number(t.text);
  if (!v || !words::valid_percent(*v))
    return fail(ErrorId::PlcScenarioBadNumber, t.column, words::not_a_percent(detail::printable(t.text)));
  pct = *v;
  return true;
}

// skip_mask <mask>: levels /1../10 as bits 0..9, decimal or 0x hexadecimal.
bool LineParser::take_skip_mask(std::uint32_t& mask) {
  if (!need("the skip mask (e.g. 0x5 for /1 and /3)")) return false;
  const Token& t = toks_[next_++];
  std::uint32_t v = 0;
  const bool hex = t.text.size() > 2 && t.text[0] == '0' && (t.text[1] == 'x' || t.text[1] == 'X');
  const std::string_view digits = hex ? t.text.substr(2) : t.text;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v, hex ? 16 : 10);
  if (ec != std::errc{} || end != digits.data() + digits.size() || digits.empty() || v > words::kAllSkipLevels)
    return fail(ErrorId::PlcScenarioBadNumber, t.column, words::not_a_skip_mask(detail::printable(t.text)));
  mask = v;
  return true;
}

// mdi <NC block>: the rest of the line (a '#' starts the scenario's comment).
bool LineParser::take_mdi_text() {
  if (!need(words::kMissingMdiText)) return false;
  const char* first = toks_[next_].text.data();
  const Token& last = toks_.back();
  mdi_text_.assign(first, static_cast<std::size_t>(last.text.data() + last.text.size() - first));
  next_ = toks_.size();
  return true;
}

bool LineParser::take_whole(std::string_view what, std::int64_t lowest, std::int64_t& value) {
  if (!need(what)) return false;
  const Token& t = toks_[next_++];
  const auto v = detail::to_number(t.text);
  if (!v || *v != std::floor(*v) || *v < static_cast<double>(lowest) || *v > 1e15)
    return fail(ErrorId::PlcScenarioBlockSearch, t.column,
                fmt::format("'{}' is not {}", detail::printable(t.text), what));
  value = static_cast<std::int64_t>(*v);
  return true;
}

// block_search N<n> | block <K> | offset <bytes> [pass <P>] [covered <per
// mille>] [program <name>] [no_hold]: the run starts with a block search
// (TF5200 types 4, 3, 1); only at time 0, where the program starts.
bool LineParser::take_block_search(const ScenarioAction& a, act::BlockSearch& b) {
  if (a.t_s != 0 || a.trigger)
    return fail(ErrorId::PlcScenarioBlockSearch, toks_[0].column,
                "block_search starts the program with a block search: give it at time 0");
  if (!take_search_mark(b)) return false;
  while (!at_end()) {
    const Token& k = toks_[next_++];
    std::int64_t v = 0;
    if (iequals(k.text, "pass")) {
      if (!take_whole("a pass count >= 1", 1, v)) return false;
      b.pass = static_cast<std::uint32_t>(std::min<std::int64_t>(v, UINT32_MAX));
    } else if (iequals(k.text, "covered")) {
      if (!take_whole("a covered share in per mille (0..1000)", 0, v)) return false;
      if (v > 1000) return fail(ErrorId::PlcScenarioBlockSearch, k.column, "covered is per mille: 0..1000");
      b.covered_permille = static_cast<double>(v);
    } else if (iequals(k.text, "program")) {
      if (!need("the program name")) return false;
      const Token& p = toks_[next_++];
      if (p.text.size() >= b.program.size())
        return fail(ErrorId::PlcScenarioBlockSearch, p.column, "the program name is too long");
      words::copy_name(p.text, b.program);
    } else if (iequals(k.text, "no_hold")) {
      b.no_hold_at_restart = true;
    } else {
      return fail(ErrorId::PlcScenarioBlockSearch, k.column,
                  fmt::format("'{}' is no block_search option: pass, covered, program or no_hold",
                              detail::printable(k.text)));
    }
  }
  return true;
}

bool LineParser::take_search_mark(act::BlockSearch& b) {
  if (!need("the restart mark: N<n>, block <K> or offset <bytes>")) return false;
  const Token& t = toks_[next_];
  std::int64_t v = 0;
  if (t.text.size() > 1 && (t.text[0] == 'N' || t.text[0] == 'n') && std::isdigit(static_cast<unsigned char>(t.text[1]))) {
    b.mark_kind = prep::SearchMark::Kind::block_number;
    std::int64_t n = 0;
    const auto [end, ec] = std::from_chars(t.text.data() + 1, t.text.data() + t.text.size(), n);
    if (ec != std::errc{} || end != t.text.data() + t.text.size())
      return fail(ErrorId::PlcScenarioBlockSearch, t.column,
                  fmt::format("'{}' is not a block number; write e.g. N100", detail::printable(t.text)));
    ++next_;
    b.mark_value = n;
    return true;
  }
  ++next_;
  if (iequals(t.text, "block")) {
    b.mark_kind = prep::SearchMark::Kind::block_counter;
    if (!take_whole("a block counter >= 1", 1, v)) return false;
  } else if (iequals(t.text, "offset")) {
    b.mark_kind = prep::SearchMark::Kind::file_offset;
    if (!take_whole("a byte offset >= 0", 0, v)) return false;
  } else {
    return fail(ErrorId::PlcScenarioBlockSearch, t.column,
                fmt::format("'{}' is no restart mark; write N<n>, block <K> or offset <bytes>",
                            detail::printable(t.text)));
  }
  b.mark_value = v;
  return true;
}

// REV / POS with the value joined (REV500, REV=500) or as the next word (REV 500).
bool LineParser::take_keyword_value(std::string_view key, double& value, bool& seen) {
  const Token& t = toks_[next_++];
  if (seen)
    return fail(ErrorId::PlcScenarioBadSpindleCommand, t.column,
                fmt::format("{} is given twice", key));
  std::string_view rest = t.text.substr(key.size());
  if (!rest.empty() && rest.front() == '=') rest.remove_prefix(1);
  std::uint32_t column = t.column;
  if (rest.empty()) {
    if (!need(fmt::format("the value after {}", key))) return false;
    rest = toks_[next_].text;
    column = toks_[next_++].column;
  }
  auto v = detail::to_number(rest);
  const bool is_rev = key == "REV";
  if (!v || (is_rev && *v < 0))
    return fail(ErrorId::PlcScenarioBadNumber, column,
                fmt::format("'{}' is not a valid {} value; write {}", detail::printable(rest), key,
                            is_rev ? "a speed in rpm >= 0" : "a position in degrees"));
  value = *v;
  seen = true;
  return true;
}

bool LineParser::take_spindle_cmd(std::uint8_t channel, act::SpindleCmd& sc) {
  plc::ExtSpindleCommand& c = sc.cmd;
  c.channel = channel;
  c.spindle_name = sc.spindle.name;
  bool have_fn = false;
  while (!at_end()) {
    const Token& t = toks_[next_];
    if (detail::istarts_with(t.text, "REV")) {
      if (!take_keyword_value("REV", c.rev_rpm, c.has_rev)) return false;
    } else if (detail::istarts_with(t.text, "POS")) {
      if (!take_keyword_value("POS", c.pos_deg, c.has_pos)) return false;
    } else if (auto fn = detail::spindle_function(t.text)) {
      if (have_fn)
        return fail(ErrorId::PlcScenarioBadSpindleCommand, t.column,
                    "only one of M3/M4/M5/M19 per command");
      c.fn = static_cast<plc::ExtFunction>(*fn);
      have_fn = true;
      ++next_;
    } else {
      return fail(ErrorId::PlcScenarioBadSpindleCommand, t.column,
                  fmt::format("'{}' is not part of a spindle command; write M3|M4|M5|M19, "
                              "REV<rpm>, POS<deg>",
                              detail::printable(t.text)));
    }
  }
  const std::uint32_t col = toks_.front().column;
  if (!have_fn)
    return fail(ErrorId::PlcScenarioBadSpindleCommand, col,
                "the spindle command names no M3/M4/M5/M19");
  if (c.fn == plc::ExtFunction::m5 && (c.has_rev || c.has_pos))
    return fail(ErrorId::PlcScenarioBadSpindleCommand, col, "M5 takes neither REV nor POS");
  if (c.has_pos && c.fn != plc::ExtFunction::m19)
    return fail(ErrorId::PlcScenarioBadSpindleCommand, col, "POS needs M19");
  return true;
}

}  // namespace

std::string_view action_name(ActionKind k) noexcept {
  for (const auto& s : kActions)
    if (s.kind == k) return s.word;
  return "?";
}

std::optional<ScenarioSearch> block_search_of(const Scenario& sc) {
  for (const ScenarioAction& a : sc.actions) {
    const auto* b = a.get<act::BlockSearch>();
    if (!b) continue;
    ScenarioSearch s;
    s.channel = a.channel >= 1 ? a.channel - 1u : 0u;
    s.mark.kind = b->mark_kind;
    s.mark.value = b->mark_value;
    s.mark.pass = b->pass;
    s.mark.covered_permille = b->covered_permille;
    s.mark.program = std::string(b->program.data());
    s.mark.no_hold_at_restart = b->no_hold_at_restart;
    return s;
  }
  return std::nullopt;
}

Scenario parse_scenario(std::string_view text, std::string file, Diagnostics& diags) {
  Scenario sc;
  sc.file = std::move(file);
  std::uint32_t line_no = 0;
  double last_t_s = 0;
  std::vector<Token> toks;
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    std::string_view line = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    ++line_no;
    detail::tokenize(line, toks);
    if (toks.empty()) continue;
    if (sc.actions.size() + sc.triggered.size() >= kMaxScenarioActions) {
      diags.add(ErrorId::PlcScenarioTooLarge, SourceLoc{sc.file, line_no, 1},
                fmt::format("more than {} actions; the rest of the file is ignored",
                            kMaxScenarioActions));
      break;
    }
    LineParser parser(toks, sc.file, line_no, diags);
    auto a = parser.parse();
    if (!a) continue;
    if (auto* mdi = a->get<act::Mdi>()) {
      mdi->text = static_cast<std::uint32_t>(sc.texts.size());
      sc.texts.push_back(parser.mdi_text());
    }
    if (a->trigger) {  // waits for its program state: no place in the timeline
      sc.triggered.push_back(*a);
      continue;
    }
    if (a->t_s < last_t_s)
      diags.add(ErrorId::PlcScenarioTimeBackwards, SourceLoc{sc.file, line_no, 1},
                fmt::format("time {} s comes after {} s; the action is sorted in by its time",
                            a->t_s, last_t_s));
    last_t_s = std::max(last_t_s, a->t_s);
    if (a->kind() == ActionKind::block_search && block_search_of(sc)) {
      diags.add(ErrorId::PlcScenarioBlockSearch, SourceLoc{sc.file, line_no, 1},
                "a second block_search line; a run has one block search");
      continue;
    }
    sc.actions.push_back(*a);
  }
  std::stable_sort(sc.actions.begin(), sc.actions.end(),
                   [](const ScenarioAction& x, const ScenarioAction& y) { return x.t_s < y.t_s; });
  return sc;
}

}  // namespace nck::sim
