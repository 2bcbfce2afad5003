// setup: parsing of --plc scenario files (grammar: docs/plc-scenario.md).
#include <cctype>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "nck/core/edit_distance.hpp"
#include "nck/sim/scenario.hpp"
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
  bool take_spindle(ScenarioAction& a);
  bool take_switch(bool& on);
  bool take_percent(double& pct);
  bool take_spindle_cmd(ScenarioAction& a);
  bool take_handwheel(ScenarioAction& a);
  bool take_axis(ScenarioAction& a);
  bool take_jog(ScenarioAction& a);
  bool take_jog_increment(ScenarioAction& a);
  bool take_jog_direction(ScenarioAction& a, bool stop_allowed);
  bool take_mode(ScenarioAction& a);
  bool take_variable(ScenarioAction& a);
  bool take_skip_mask(double& mask);
  bool take_block_search(ScenarioAction& a);
  bool take_mdi_text();
  bool take_search_mark(ScenarioAction& a);
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
                     detail::printable(toks_[next_].text), action_name(a.kind)));
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
  if (!v || *v < 1 || *v > static_cast<double>(config::kMaxChannels) || *v != std::floor(*v))
    return fail(ErrorId::PlcScenarioBadChannel, column,
                fmt::format("'{}' is not a channel number; write a whole number 1..{}",
                            detail::printable(num_text), config::kMaxChannels));
  a.channel = static_cast<std::uint8_t>(*v);
  return true;
}

bool LineParser::parse_action(ScenarioAction& a) {
  if (!need("an action after the time (e.g. feed_override 80)")) return false;
  const Token& t = toks_[next_++];
  for (const auto& s : kActions) {
    if (iequals(t.text, s.word)) {
      a.kind = s.kind;
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

bool LineParser::parse_args(ScenarioAction& a) {
  switch (a.kind) {
    case ActionKind::spindle_override:
      return take_spindle(a) && take_percent(a.value);
    case ActionKind::feed_override:
    case ActionKind::rapid_override:
      return take_percent(a.value);
    case ActionKind::override_valid:
    case ActionKind::spindle_feedhold:
      return take_spindle(a) && take_switch(a.on);
    case ActionKind::spindle_stop_at_end:
      if (!take_switch(a.on)) return false;
      return at_end() || take_spindle(a);  // optional spindle
    case ActionKind::feedhold:
    case ActionKind::optional_stop:
    case ActionKind::silent:
    case ActionKind::auto_cycle_start:
    case ActionKind::single_step:
      return take_switch(a.on);
    case ActionKind::reset:
    case ActionKind::stop:
    case ActionKind::cycle_start:
      return true;
    case ActionKind::spindle_reset:
      return take_spindle(a);
    case ActionKind::spindle_cmd:
      return take_spindle(a) && take_spindle_cmd(a);
    case ActionKind::handwheel:
      return take_handwheel(a);
    case ActionKind::variable:
      return take_variable(a);
    case ActionKind::skip_mask:
      return take_skip_mask(a.value);
    case ActionKind::block_search:
      return take_block_search(a);
    case ActionKind::mdi:
      return take_mdi_text();
    case ActionKind::jog:
      return take_jog(a);
    case ActionKind::jog_increment:
      return take_jog_increment(a);
    case ActionKind::mode:
      return take_mode(a);
  }
  return true;
}

// A path axis name as the channel knows it (checked against the machine later).
bool LineParser::take_axis(ScenarioAction& a) {
  if (!need("the axis name (e.g. X)")) return false;
  const Token& axis = toks_[next_++];
  if (axis.text.empty() || axis.text.size() >= a.axis_name.size() ||
      !std::isalpha(static_cast<unsigned char>(axis.text[0])))
    return fail(ErrorId::PlcScenarioBadNumber, axis.column,
                fmt::format("'{}' is not an axis name; write e.g. X", detail::printable(axis.text)));
  std::copy(axis.text.begin(), axis.text.end(), a.axis_name.begin());
  a.axis_name[axis.text.size()] = '\0';
  return true;
}

// handwheel <axis> <mm>: the axis name as the channel knows it, the distance signed.
bool LineParser::take_handwheel(ScenarioAction& a) {
  if (!take_axis(a)) return false;
  if (!need("the handwheel distance in mm")) return false;
  const Token& t = toks_[next_++];
  auto v = detail::to_number(t.text);
  if (!v)
    return fail(ErrorId::PlcScenarioBadNumber, t.column,
                fmt::format("'{}' is not a distance; write mm, e.g. 0.5", detail::printable(t.text)));
  a.value = *v;
  return true;
}

// + or - (or stop, where allowed): the jog's direction.
bool LineParser::take_jog_direction(ScenarioAction& a, bool stop_allowed) {
  if (!need(stop_allowed ? "+, - or stop" : "+ or -")) return false;
  const Token& t = toks_[next_++];
  if (t.text == "+") a.direction = 1;
  else if (t.text == "-") a.direction = -1;
  else if (stop_allowed && iequals(t.text, "stop")) a.direction = 0;
  else
    return fail(ErrorId::PlcScenarioBadJog, t.column,
                fmt::format("'{}' is not a jog direction; write {}", detail::printable(t.text),
                            stop_allowed ? "+, - or stop" : "+ or -"));
  return true;
}

// jog <axis> +|- [speed mm/min] | jog <axis> stop: a continuous jog starts
// (until its stop line) or is released. The speed is kept in mm/s.
bool LineParser::take_jog(ScenarioAction& a) {
  if (!take_axis(a) || !take_jog_direction(a, true)) return false;
  if (at_end() || a.direction == 0) return true;
  const Token& t = toks_[next_++];
  auto v = detail::to_number(t.text);
  if (!v || *v <= 0)
    return fail(ErrorId::PlcScenarioBadJog, t.column,
                fmt::format("'{}' is not a jog speed; write mm/min > 0, e.g. 600", detail::printable(t.text)));
  a.value = *v / 60.0;
  return true;
}

// jog_increment <axis> +|- <step mm>: one step per line.
bool LineParser::take_jog_increment(ScenarioAction& a) {
  if (!take_axis(a) || !take_jog_direction(a, false)) return false;
  if (!need("the step in mm (e.g. 0.1)")) return false;
  const Token& t = toks_[next_++];
  auto v = detail::to_number(t.text);
  if (!v || *v <= 0)
    return fail(ErrorId::PlcScenarioBadJog, t.column,
                fmt::format("'{}' is not a jog step; write mm > 0, e.g. 0.1", detail::printable(t.text)));
  a.value = *v;
  return true;
}

// mode manual|automatic: on = manual.
bool LineParser::take_mode(ScenarioAction& a) {
  if (!need("manual or automatic")) return false;
  const Token& t = toks_[next_++];
  if (iequals(t.text, "manual")) a.on = true;
  else if (iequals(t.text, "automatic")) a.on = false;
  else
    return fail(ErrorId::PlcScenarioBadMode, t.column,
                fmt::format("'{}' is not a mode; write manual or automatic", detail::printable(t.text)));
  return true;
}

// variable <name> <value>: a channel variable (e.g. the distance sensor's
// value for SENSOR_SOURCE=VARIABLE), matched by name, case-insensitively.
bool LineParser::take_variable(ScenarioAction& a) {
  if (!need("the variable name (e.g. V.E.GAP)")) return false;
  const Token& name = toks_[next_++];
  if (name.text.empty() || name.text.size() >= a.var_name.size())
    return fail(ErrorId::PlcScenarioBadNumber, name.column,
                fmt::format("'{}' is not a variable name (1 to {} characters)", detail::printable(name.text),
                            a.var_name.size() - 1));
  for (std::size_t i = 0; i < name.text.size(); ++i)
    a.var_name[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(name.text[i])));
  if (!need("the variable's value")) return false;
  const Token& t = toks_[next_++];
  auto v = detail::to_number(t.text);
  if (!v)
    return fail(ErrorId::PlcScenarioBadNumber, t.column,
                fmt::format("'{}' is not a number", detail::printable(t.text)));
  a.value = *v;
  return true;
}

bool LineParser::take_spindle(ScenarioAction& a) {
  if (!need("the spindle name (e.g. S1)")) return false;
  const Token& t = toks_[next_++];
  if (!detail::valid_spindle_name(t.text))
    return fail(ErrorId::PlcScenarioBadSpindleName, t.column,
                fmt::format("'{}' is not a spindle name; write S or S followed by letters, digits "
                            "or _ (at most {} characters), e.g. S1",
                            detail::printable(t.text), plc::kSpindleNameChars - 1));
  std::copy(t.text.begin(), t.text.end(), a.spindle_name.begin());
  a.spindle_name[t.text.size()] = '\0';
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
  if (!v || *v < 0 || *v > kMaxOverridePercent)
    return fail(ErrorId::PlcScenarioBadNumber, t.column,
                fmt::format("'{}' is not an override; write a percentage from 0 to {}",
                            detail::printable(t.text), kMaxOverridePercent));
  pct = *v;
  return true;
}

// skip_mask <mask>: levels /1../10 as bits 0..9, decimal or 0x hexadecimal.
bool LineParser::take_skip_mask(double& mask) {
  if (!need("the skip mask (e.g. 0x5 for /1 and /3)")) return false;
  const Token& t = toks_[next_++];
  std::uint32_t v = 0;
  const bool hex = t.text.size() > 2 && t.text[0] == '0' && (t.text[1] == 'x' || t.text[1] == 'X');
  const std::string_view digits = hex ? t.text.substr(2) : t.text;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v, hex ? 16 : 10);
  if (ec != std::errc{} || end != digits.data() + digits.size() || digits.empty() || v > 0x3FF)
    return fail(ErrorId::PlcScenarioBadNumber, t.column,
                fmt::format("'{}' is not a skip mask; write 0 to 1023 (0x3FF): bit 0 = /1 ... bit 9 = /10",
                            detail::printable(t.text)));
  mask = v;
  return true;
}

// mdi <NC block>: the rest of the line (a '#' starts the scenario's comment).
bool LineParser::take_mdi_text() {
  if (!need("the NC block to run (e.g. G1 X10 F1000)")) return false;
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
bool LineParser::take_block_search(ScenarioAction& a) {
  if (a.t_s != 0 || a.trigger)
    return fail(ErrorId::PlcScenarioBlockSearch, toks_[0].column,
                "block_search starts the program with a block search: give it at time 0");
  if (!take_search_mark(a)) return false;
  while (!at_end()) {
    const Token& k = toks_[next_++];
    std::int64_t v = 0;
    if (iequals(k.text, "pass")) {
      if (!take_whole("a pass count >= 1", 1, v)) return false;
      a.search_pass = static_cast<std::uint32_t>(std::min<std::int64_t>(v, UINT32_MAX));
    } else if (iequals(k.text, "covered")) {
      if (!take_whole("a covered share in per mille (0..1000)", 0, v)) return false;
      if (v > 1000) return fail(ErrorId::PlcScenarioBlockSearch, k.column, "covered is per mille: 0..1000");
      a.covered_permille = static_cast<double>(v);
    } else if (iequals(k.text, "program")) {
      if (!need("the program name")) return false;
      const Token& p = toks_[next_++];
      if (p.text.size() >= a.program.size())
        return fail(ErrorId::PlcScenarioBlockSearch, p.column, "the program name is too long");
      std::copy(p.text.begin(), p.text.end(), a.program.begin());
    } else if (iequals(k.text, "no_hold")) {
      a.on = true;
    } else {
      return fail(ErrorId::PlcScenarioBlockSearch, k.column,
                  fmt::format("'{}' is no block_search option: pass, covered, program or no_hold",
                              detail::printable(k.text)));
    }
  }
  return true;
}

bool LineParser::take_search_mark(ScenarioAction& a) {
  if (!need("the restart mark: N<n>, block <K> or offset <bytes>")) return false;
  const Token& t = toks_[next_];
  std::int64_t v = 0;
  if (t.text.size() > 1 && (t.text[0] == 'N' || t.text[0] == 'n') && std::isdigit(static_cast<unsigned char>(t.text[1]))) {
    a.search_kind = prep::SearchMark::Kind::block_number;
    std::int64_t n = 0;
    const auto [end, ec] = std::from_chars(t.text.data() + 1, t.text.data() + t.text.size(), n);
    if (ec != std::errc{} || end != t.text.data() + t.text.size())
      return fail(ErrorId::PlcScenarioBlockSearch, t.column,
                  fmt::format("'{}' is not a block number; write e.g. N100", detail::printable(t.text)));
    ++next_;
    a.value = static_cast<double>(n);
    return true;
  }
  ++next_;
  if (iequals(t.text, "block")) {
    a.search_kind = prep::SearchMark::Kind::block_counter;
    if (!take_whole("a block counter >= 1", 1, v)) return false;
  } else if (iequals(t.text, "offset")) {
    a.search_kind = prep::SearchMark::Kind::file_offset;
    if (!take_whole("a byte offset >= 0", 0, v)) return false;
  } else {
    return fail(ErrorId::PlcScenarioBlockSearch, t.column,
                fmt::format("'{}' is no restart mark; write N<n>, block <K> or offset <bytes>",
                            detail::printable(t.text)));
  }
  a.value = static_cast<double>(v);
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

bool LineParser::take_spindle_cmd(ScenarioAction& a) {
  plc::ExtSpindleCommand& c = a.cmd;
  c.channel = a.channel;
  c.spindle_name = a.spindle_name;
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
    if (a.kind != ActionKind::block_search) continue;
    ScenarioSearch s;
    s.channel = a.channel >= 1 ? a.channel - 1u : 0u;
    s.mark.kind = a.search_kind;
    s.mark.value = static_cast<std::int64_t>(a.value);
    s.mark.pass = a.search_pass;
    s.mark.covered_permille = a.covered_permille;
    s.mark.program = std::string(a.program.data());
    s.mark.no_hold_at_restart = a.on;
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
    if (a->kind == ActionKind::mdi) {
      a->value = static_cast<double>(sc.texts.size());
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
    if (a->kind == ActionKind::block_search && block_search_of(sc)) {
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
