// Spindle words: DIN syntax of the main spindle (S1000, S.POS=90,
// S.POS_SHIFT=.., S.OFFSET=..) and the spindle-specific syntax
// S1[M3 REV1000 ...] with the keywords of TF5200's spindle-specific syntax
// (listed in docs/nc-language.md, "Spindles").
#include <cmath>
#include <fmt/format.h>

#include "block_words.hpp"

namespace nck::nc::detail {

namespace {

// Configured spindle name for `name`, checking the main-spindle rules.
bool resolve_spindle(BlockCtx& b, const std::string& name, bool din, std::size_t pos,
                     std::string& target) {
  if (iequals(name, b.cfg.main_spindle_name)) {
    target = b.main_target;
    return true;
  }
  for (const auto& s : b.cfg.spindle_names) {
    if (!iequals(s, name)) continue;
    if (iequals(s, b.main_target))
      return b.x.err.fail(ErrorId::NcMainSpindleByOwnName, pos,
                          fmt::format("{} is the main spindle: address it as {}", s,
                                      b.cfg.main_spindle_name));
    if (din)
      return b.x.err.fail(ErrorId::NcDinForNonMainSpindle, pos,
                          fmt::format("{} is not the main spindle: use {}[..] (e.g. {}[M3 REV1000])", s, s, s));
    target = s;
    return true;
  }
  return b.x.err.fail(ErrorId::NcUnknownSpindle, pos,
                      fmt::format("spindle '{}' is not configured in this channel", name));
}

bool value_after(Cursor& c, BlockCtx& b, double& v, std::string_view what) {
  c.skip_spaces();
  c.match('=');
  c.skip_spaces();
  if (c.at_end() || c.peek() == ']')
    return b.x.err.fail(ErrorId::NcSpindleKeyword, c.pos, fmt::format("{} needs a value", what));
  return eval_value(c, b.x, v);
}

bool int_value(BlockCtx& b, double v, std::size_t pos, int& out, std::string_view what) {
  double r = std::round(v);
  if (r < 0 || r > 1e9)
    return b.x.err.fail(ErrorId::NcBadMFunction, pos, fmt::format("{} needs an integer >= 0", what));
  out = static_cast<int>(r);
  return true;
}

bool parse_feed_link(Cursor& c, BlockCtx& b, SpindleCommand& sc) {
  FeedLink fl;
  for (;;) {
    c.skip_spaces();
    double v = 0;
    if (c.match_keyword("ON")) fl.on = true;
    else if (c.match_keyword("OFF")) fl.on = false;
    else if (c.match_keyword("AUTO")) fl.automatic = true;
    else if (c.match_keyword("MAIN")) fl.main = true;
    else if (c.match_keyword("FACT")) {
      if (!value_after(c, b, v, "FACT")) return false;
      fl.fact_pct = v * 0.1;
    } else if (c.match_keyword("CORR")) {
      if (!value_after(c, b, v, "CORR")) return false;
      fl.corr = v;
    } else if (c.match_keyword("SRC")) {
      c.skip_spaces();
      c.match('=');
      c.skip_spaces();
      std::size_t b0 = c.pos;
      while (!c.at_end() && c.peek() != ' ' && c.peek() != ']') ++c.pos;
      fl.src = std::string(c.s.substr(b0, c.pos - b0));
      if (fl.src.empty()) return b.x.err.fail(ErrorId::NcSpindleKeyword, b0, "SRC= needs a source");
    } else {
      break;
    }
  }
  sc.feed_link = std::move(fl);
  return true;
}

// Checks the combination rules of one bracket (docs/nc-language.md, "Spindles").
bool check_bracket(BlockCtx& b, const SpindleCommand& sc, int m_count, int g136_count,
                   int other_count, std::size_t pos) {
  if (m_count > 0)
    return b.x.err.fail(ErrorId::NcSpindleMConflict, pos,
                        fmt::format("{}[..] has more than one of M3/M4/M5/M19; program one", sc.name));
  if (g136_count > 1)
    return b.x.err.fail(ErrorId::NcSpindleG136Twice, pos, "G136 is programmed twice; keep one");
  if (sc.g136_pct && sc.g130_pct)
    return b.x.err.fail(ErrorId::NcSpindleG136WithG130, pos, "G136 and G130 cannot share a spindle command");
  if (sc.g74 && sc.m != SpindleM::none)
    return b.x.err.fail(ErrorId::NcG74WithSpindleM, pos, "G74 homing cannot share a block with M3/M4/M5/M19");
  bool dyn = sc.get_dynamic_data || sc.default_dynamic_data;
  if (dyn && (other_count > 1))
    return b.x.err.fail(ErrorId::NcSpindleCombination, pos,
                        "GET/DEFAULT_DYNAMIC_DATA must stand alone in the spindle command");
  bool ff = sc.g135 || sc.g137;
  if (sc.g135 && sc.g137)
    return b.x.err.fail(ErrorId::NcSpindleCombination, pos, "G135 and G137 exclude each other");
  // The manual's own example combines G135/G136 with M4 and REV, so only
  // the other special functions are excluded here.
  if (ff && (sc.g74 || sc.g130_pct || sc.g167 || sc.callax || sc.putax || dyn))
    return b.x.err.fail(ErrorId::NcSpindleCombination, pos,
                        "G135/G137 cannot share a spindle command with G74, G130, G167, CALLAX/PUTAX or dynamic data");
  if (sc.callax && sc.putax)
    return b.x.err.fail(ErrorId::NcSpindleCombination, pos, "CALLAX and PUTAX exclude each other");
  return true;
}

bool parse_bracket(Cursor& c, BlockCtx& b, SpindleCommand& sc) {
  std::size_t open = c.pos - 1;
  int m_count = 0, g136_count = 0, other = 0;
  bool m19 = false;
  SpindleM dir = SpindleM::none;
  auto set_m = [&](SpindleM m, std::size_t pos) {
    if (m == SpindleM::m19) {
      if (m19) ++m_count;
      m19 = true;
    } else {
      if (dir != SpindleM::none) ++m_count;
      dir = m;
    }
    if (m19 && dir == SpindleM::m5)
      return b.x.err.fail(ErrorId::NcM19WithM5, pos, "M19 cannot be combined with M5 for one spindle");
    sc.m = m19 ? SpindleM::m19 : dir;
    sc.direction = m19 ? dir : SpindleM::none;
    return true;
  };
  for (;;) {
    c.skip_blanks();
    if (c.at_end())
      return b.x.err.fail(ErrorId::NcExprSyntax, open,
                          fmt::format("{}[ is not closed with ']'", sc.name));
    if (c.match(']')) break;
    std::size_t pos = c.pos;
    double v = 0;
    ++other;
    if (c.match_keyword("DEFAULT_DYNAMIC_DATA") || c.match_keyword("DEFAULT_DYNAMIK_DATA") ||
        c.match_keyword("DEFAUL_DYNAMIK_DATA")) {
      sc.default_dynamic_data = true;
    } else if (c.match_keyword("GET_DYNAMIC_DATA") || c.match_keyword("GET_DYNAMIK_DATA")) {
      sc.get_dynamic_data = true;
    } else if (c.match_keyword("CALLAX")) {
      sc.callax = true;
    } else if (c.match_keyword("PUTAX")) {
      sc.putax = true;
    } else if (c.match_keyword("OVERRIDE")) {
      c.skip_spaces();
      if (!c.match_keyword("SPEED_FACT"))
        return b.x.err.fail(ErrorId::NcSpindleKeyword, c.pos, "OVERRIDE needs SPEED_FACT=<percent>");
      if (!value_after(c, b, v, "SPEED_FACT")) return false;
      if (v < 0.1 || v > 200)
        return b.x.err.fail(ErrorId::NcOverrideRange, pos,
                            fmt::format("SPEED_FACT={} is outside 0.1..200 %", v));
      sc.override_speed_fact_pct = v;
    } else if (c.match_keyword("FEED_LINK")) {
      if (!parse_feed_link(c, b, sc)) return false;
    } else if (c.match_prefix("REV") && !is_alpha(c.peek()) && c.peek() != '_') {
      if (!value_after(c, b, v, "REV")) return false;
      if (v < 0)
        return b.x.err.fail(ErrorId::NcNegativeSpeed, pos, fmt::format("REV {} is negative", v));
      sc.rev_rpm = v;
    } else if (c.match_prefix("POS") && !is_alpha(c.peek()) && c.peek() != '_') {
      if (!value_after(c, b, v, "POS")) return false;
      sc.pos_deg = v;
    } else if ((upper(c.peek()) == 'M' || upper(c.peek()) == 'H') &&
               (c.peek(1) == '=' || c.peek(1) == ' ')) {
      char a = upper(c.get());
      if (!value_after(c, b, v, a == 'M' ? "M=" : "H=")) return false;
      int code = 0;
      if (!int_value(b, v, pos, code, a == 'M' ? "M=" : "H=")) return false;
      (a == 'M' ? sc.user_m : sc.user_h).push_back(code);
    } else if (upper(c.peek()) == 'M' && is_digit(c.peek(1))) {
      ++c.pos;
      int code = 0;
      while (is_digit(c.peek()) && code < 100000) code = code * 10 + (c.get() - '0');
      SpindleM m = code == 3 ? SpindleM::m3 : code == 4 ? SpindleM::m4 : code == 5 ? SpindleM::m5
                 : code == 19 ? SpindleM::m19 : SpindleM::none;
      if (m == SpindleM::none)
        return b.x.err.fail(ErrorId::NcSpindleKeyword, pos,
                            fmt::format("M{} is not a spindle function; user M functions are written M={}", code, code));
      if (!set_m(m, pos)) return false;
    } else if (upper(c.peek()) == 'G' && is_digit(c.peek(1))) {
      ++c.pos;
      int code = 0;
      while (is_digit(c.peek()) && code < 100000) code = code * 10 + (c.get() - '0');
      switch (code) {
        case 74: sc.g74 = true; break;
        case 167: sc.g167 = true; break;
        case 135: sc.g135 = true; break;
        case 137: sc.g137 = true; break;
        case 130:
          if (!value_after(c, b, v, "G130")) return false;
          if (v <= 0) return b.x.err.fail(ErrorId::NcSpindleKeyword, pos, "G130 weighting must be > 0 %");
          sc.g130_pct = v;
          break;
        case 136:
          if (!value_after(c, b, v, "G136")) return false;
          if (v < 0 || v > 100)
            return b.x.err.fail(ErrorId::NcSpindleKeyword, pos, "G136 weighting must be 0..100 %");
          ++g136_count;
          sc.g136_pct = v;
          break;
        default:
          return b.x.err.fail(ErrorId::NcSpindleKeyword, pos,
                              fmt::format("G{} is not allowed in a spindle command", code));
      }
    } else {
      return b.x.err.fail(ErrorId::NcSpindleKeyword, pos,
                          fmt::format("'{}' is not a spindle keyword (M3 M4 M5 M19 REV POS M= H= G74 "
                                      "G130 G135 G136 G137 G167 CALLAX PUTAX GET_/DEFAULT_DYNAMIC_DATA "
                                      "OVERRIDE FEED_LINK)", c.peek()));
    }
  }
  return check_bracket(b, sc, m_count, g136_count, other, open);
}

}  // namespace

bool parse_spindle_word(Cursor& c, BlockCtx& b, Words& w) {
  std::size_t pos = c.pos;
  std::size_t e = pos + 1;
  while (e < c.s.size() && is_ident_char(c.s[e])) ++e;
  char next = e < c.s.size() ? c.s[e] : '\0';
  std::string name;
  if (next == '[' || next == '=' || next == '.') {
    name = to_upper(c.s.substr(pos, e - pos));
    c.pos = e;
  } else {
    name = to_upper(b.cfg.main_spindle_name);  // S1000: the main spindle's speed
    c.pos = pos + 1;
  }
  if (next == '[') {
    SpindleCommand sc;
    sc.name = name;
    sc.column = static_cast<std::uint32_t>(pos);
    if (!resolve_spindle(b, name, false, pos, sc.target)) return false;
    for (const auto& o : w.brackets)
      if (o.target == sc.target)
        return b.x.err.fail(ErrorId::NcSpindleTwice, pos,
                            fmt::format("spindle {} is programmed twice in this block", name));
    ++c.pos;
    if (!parse_bracket(c, b, sc)) return false;
    w.brackets.push_back(std::move(sc));
    return true;
  }
  std::string target;
  if (!resolve_spindle(b, name, true, pos, target)) return false;
  if (!w.din_spindle_pos) w.din_spindle_pos = static_cast<std::uint32_t>(pos + 1);
  double v = 0;
  if (c.peek() == '.') {
    ++c.pos;
    At<double>* slot = nullptr;
    std::string_view what;
    if (c.match_keyword("POS_SHIFT") || c.match_prefix("POS_SHIFT")) { slot = &w.s_pos_shift; what = "POS_SHIFT"; }
    else if (c.match_prefix("POS")) { slot = &w.s_pos; what = "POS"; }
    else if (c.match_prefix("OFFSET")) { slot = &w.s_offset; what = "OFFSET"; }
    else
      return b.x.err.fail(ErrorId::NcSpindleKeyword, c.pos,
                          fmt::format("{}. must be followed by POS, POS_SHIFT or OFFSET", name));
    if (!value_after(c, b, v, what)) return false;
    if (slot->v)
      return b.x.err.fail(ErrorId::NcDuplicateWord, pos, fmt::format("{}.{} is programmed twice", name, what));
    slot->set(v, pos);
    return true;
  }
  c.skip_spaces();
  c.match('=');
  c.skip_spaces();
  if (c.at_end())
    return b.x.err.fail(ErrorId::NcBadValue, pos, fmt::format("{} needs a value", name));
  if (!eval_value(c, b.x, v)) return false;
  if (w.s.v)
    return b.x.err.fail(ErrorId::NcDuplicateWord, pos, fmt::format("{} is programmed twice in this block", name));
  w.s.set(v, pos);
  return true;
}

}  // namespace nck::nc::detail
