// Stage 1 of a block: read the words and evaluate their values.
#include <bit>
#include <cmath>
#include <fmt/format.h>

#include "block_words.hpp"
#include "isg_refusals.hpp"

namespace nck::nc::detail {

void Words::clear() {
  n = {};
  g.clear();
  m.clear();
  h.clear();
  for (std::uint32_t bits = axis_mask; bits != 0; bits &= bits - 1) axes[static_cast<std::size_t>(std::countr_zero(bits))].reset();
  axis_mask = 0;
  axis_count = 0;
  f = s = t = d = r = {};
  ijk = {};
  dwell_direct = time_s = contour_dev = {};
  slope = {};
  slope_default = false;
  s_pos = s_pos_shift = s_offset = {};
  din_spindle_pos = 0;
  brackets.clear();
  hash.reset();
  hash_pos = 0;
  assigns.clear();
  word_count = 0;
  axis_dims = 0;
  axis_repeat_mask = 0;
}

int find_axis(const BlockCtx& b, std::string_view name_upper) {
  for (std::size_t i = 0; i < b.axis_upper.size() && i < kMaxAxes; ++i)
    if (b.axis_upper[i] == name_upper) return static_cast<int>(i);
  return -1;
}

int find_alias(const BlockCtx& b, std::string_view name_upper) {
  for (std::size_t i = 0; i < b.alias_upper.size() && i < kMaxAxes; ++i)
    if (!b.alias_upper[i].empty() && b.alias_upper[i] == name_upper) return static_cast<int>(i);
  return -1;
}

namespace {

// The value after an address: blanks, an optional '=', then a word value.
bool word_value(Cursor& c, BlockCtx& b, double& v, char addr) {
  c.skip_spaces();
  c.match('=');
  c.skip_spaces();
  if (c.at_end() || c.peek() == ';' || c.peek() == '(')
    return b.x.err.fail(ErrorId::NcBadValue, c.pos,
                        fmt::format("{} needs a value (number, [expression], P parameter or variable)", addr));
  return eval_value(c, b.x, v);
}

template <class T>
bool set_once(At<T>& slot, T v, std::size_t pos, BlockCtx& b, char addr) {
  if (slot.v)
    return b.x.err.fail(ErrorId::NcDuplicateWord, pos,
                        fmt::format("{} is programmed twice in this block; keep one", addr));
  slot.set(v, pos);
  return true;
}

// The G functions written G<n>=<value>: G159 (zero offset) and the group
// weightings G131/G133/G134/G233 (percent).
std::optional<GCode> valued_g(std::string_view name_upper) {
  static constexpr std::pair<std::string_view, GCode> kValued[] = {
      {"G159", GCode::g159}, {"G131", GCode::g131}, {"G133", GCode::g133}, {"G134", GCode::g134}, {"G233", GCode::g233}};
  for (const auto& [n, g] : kValued)
    if (n == name_upper) return g;
  return std::nullopt;
}

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char ch : s)
    if (!is_digit(ch)) return false;
  return true;
}

// An M or H word (`letter`) into the block's list of its kind.
bool add_function_word(BlockCtx& b, Words& w, char letter, double code, std::size_t pos,
                       std::optional<std::int32_t> value = std::nullopt) {
  auto& list = letter == 'M' ? w.m : w.h;
  if (!list.push_back(MWord{static_cast<int>(code), static_cast<std::uint32_t>(pos), value}))
    return b.x.err.fail(ErrorId::NcBadMFunction, pos, "too many M/H functions in one block");
  ++w.word_count;
  return true;
}

// M<n>=<value> / H<n>=<value> (TF5200 "M/H functions with additional
// information"): an integer, written out or computed, that the PLC gets
// with the function. `c` stands before the '='.
bool function_with_value(Cursor& c, BlockCtx& b, Words& w, const std::string& name, std::size_t pos) {
  double v = 0;
  if (!word_value(c, b, v, name[0])) return false;
  if (v != std::round(v) || !(std::abs(v) <= 2147483647.0))
    return b.x.err.fail(ErrorId::NcBadMFunction, pos,
                        fmt::format("{}={:g}: the additional value must be an integer (32 bits)", name, v));
  const double code = std::stod(name.substr(1));
  if (code > 1e9) return b.x.err.fail(ErrorId::NcBadMFunction, pos, fmt::format("{} is malformed", name));
  return add_function_word(b, w, name[0], code, pos, static_cast<std::int32_t>(v));
}

// As many digits as a block number written out may have (15, decoder.cpp).
constexpr double kMaxBlockNumber = 999'999'999'999'999.0;

bool integer_code(double v, int& code) {
  double r = std::round(v);
  if (std::fabs(v - r) > 1e-9 || r < 0 || r > 1e6) return false;
  code = static_cast<int>(r);
  return true;
}

// A G number nck has no G function for: an ISG function it does not have
// (920052), or unknown (920005); an ISO/Fanuc meaning gets its ISG remedy.
bool unknown_g(BlockCtx& b, int code, std::size_t pos) {
  const std::optional<std::string_view> iso = iso_g_remedy(code);
  if (isg_g_function(code))
    return b.x.err.fail(ErrorId::NcUnsupported, pos,
                        fmt::format("G{} is an ISG function nck does not support{}{}", code, iso ? "; " : "",
                                    iso.value_or("")));
  return b.x.err.fail(ErrorId::NcUnknownGCode, pos,
                      iso ? std::string(*iso) : fmt::format("G{} is unknown to nck; see docs/nc-language.md", code));
}

bool parse_assignment(Cursor& c, BlockCtx& b, Words& w) {
  Assignment a;
  if (!parse_lvalue(c, b.x, a.target)) return false;
  c.skip_spaces();
  if (!c.match('=')) {
    return b.x.err.fail(ErrorId::NcVariableWithoutAssignment, a.target.pos,
                        "a variable or P parameter stands alone; write NAME = value, or use it as a word value");
  }
  c.skip_spaces();
  if (c.peek() == '"') {
    std::size_t e = c.s.find('"', c.pos + 1);
    if (e == std::string_view::npos)
      return b.x.err.fail(ErrorId::NcExprSyntax, c.pos, "string without closing \"");
    a.is_string = true;
    a.str = std::string(c.s.substr(c.pos + 1, e - c.pos - 1));
    c.pos = e + 1;
  } else if (!eval_expr(c, b.x, a.value)) {
    return false;
  }
  w.assigns.push_back(std::move(a));
  ++w.word_count;
  return true;
}

bool parse_letter_word(Cursor& c, BlockCtx& b, Words& w) {
  std::size_t pos = c.pos;
  // A multi-letter name (C1, X2, G159) is followed by '='.
  std::size_t e = pos;
  while (e < c.s.size() && is_ident_char(c.s[e])) ++e;
  std::size_t eq = e;
  while (eq < c.s.size() && (c.s[eq] == ' ' || c.s[eq] == '\t')) ++eq;
  if (e - pos > 1 && eq < c.s.size() && c.s[eq] == '=') {
    std::string name = to_upper(c.s.substr(pos, e - pos));
    int ax = find_axis(b, name);
    if (ax < 0) ax = find_alias(b, name);
    c.pos = e;
    double v = 0;
    if (ax >= 0) return word_value(c, b, v, name[0]) && add_axis_word(b, w, ax, v, pos, name);
    if ((name[0] == 'M' || name[0] == 'H') && all_digits(std::string_view(name).substr(1)))
      return function_with_value(c, b, w, name, pos);
    if (const std::optional<GCode> g = valued_g(name)) {
      if (!word_value(c, b, v, 'G')) return false;
      if (!w.g.push_back(GWord{*g, static_cast<std::uint32_t>(pos), v}))
        return b.x.err.fail(ErrorId::NcModalConflict, pos, "too many G codes in one block");
      ++w.word_count;
      return true;
    }
    return b.x.err.fail(ErrorId::NcUnknownWord, pos,
                        fmt::format("'{}' is not a configured axis or known word", name));
  }
  char a = upper(c.get());
  std::string one(1, a);
  int ax = find_axis(b, one);
  double v = 0;
  if (ax >= 0) return word_value(c, b, v, a) && add_axis_word(b, w, ax, v, pos, one);
  switch (a) {
    case 'N': {
      if (!word_value(c, b, v, a)) return false;
      // TF5200 "NC block numbers": a computed number is rounded to an integer.
      const double number = std::round(v);
      if (!(number >= 0 && number <= kMaxBlockNumber))
        return b.x.err.fail(ErrorId::NcBadValue, pos,
                            fmt::format("block number N{} is not a number from 0 to {}", v, kMaxBlockNumber));
      if (!set_once(w.n, static_cast<std::int64_t>(number), pos, b, a)) return false;
      c.match(':');  // "N20:" marks a jump label
      return true;
    }
    case 'G': {
      if (!word_value(c, b, v, a)) return false;
      int code = 0;
      if (!integer_code(v, code))
        return b.x.err.fail(ErrorId::NcUnknownGCode, pos, fmt::format("G{} is not a G code", v));
      const std::optional<GCode> g = to_gcode(code);
      if (!g) return unknown_g(b, code, pos);
      if (group_weight(*g))
        return b.x.err.fail(ErrorId::NcDynWeighting, pos,
                            fmt::format("G{0} takes its weighting as G{0}=<percent>", code));
      if (!w.g.push_back(GWord{*g, static_cast<std::uint32_t>(pos), 0}))
        return b.x.err.fail(ErrorId::NcModalConflict, pos, "too many G codes in one block");
      ++w.word_count;
      return true;
    }
    case 'M':
    case 'H': {
      if (!word_value(c, b, v, a)) return false;
      double r = std::round(v);
      if (r < 0 || r > 1e9)
        return b.x.err.fail(ErrorId::NcBadMFunction, pos,
                            fmt::format("{}{} is malformed: the number must be an integer >= 0", a, v));
      return add_function_word(b, w, a, r, pos);
    }
    case 'F': case 'T': case 'D': case 'R': case 'I': case 'J': case 'K': {
      if (!word_value(c, b, v, a)) return false;
      At<double>* slot = a == 'F' ? &w.f : a == 'T' ? &w.t : a == 'D' ? &w.d : a == 'R' ? &w.r
                                                                                   : &w.ijk[a - 'I'];
      ++w.word_count;
      return set_once(*slot, v, pos, b, a);
    }
    case 'O':
      if (is_digit(c.peek())) return b.x.err.fail(ErrorId::NcUnknownWord, pos, iso_program_number(Cursor{c.s, pos}));
      [[fallthrough]];
    default:
      return b.x.err.fail(ErrorId::NcUnknownWord, pos,
                          fmt::format("'{}' is not a word of the NC language or a configured axis", a));
  }
}

}  // namespace

bool parse_words(Cursor& c, BlockCtx& b, Words& w) {
  bool exclusive_hash = false;
  while (!c.rest_empty()) {
    if (exclusive_hash)
      return b.x.err.fail(ErrorId::NcHashNotAlone, c.pos,
                          "a # command must be alone in its block (only N may precede it)");
    std::size_t pos = c.pos;
    char ch = upper(c.peek());
    if (ch == '#') {
      if (w.hash || w.time_s.v)
        return b.x.err.fail(ErrorId::NcHashNotAlone, pos, "only one # command per block");
      bool exclusive = true;
      int words_before = w.word_count;
      if (!parse_hash(c, b, w, exclusive)) return false;
      if (exclusive && words_before > 0)
        return b.x.err.fail(ErrorId::NcHashNotAlone, pos,
                            "a # command must be alone in its block (only N may precede it)");
      exclusive_hash = exclusive;
      continue;
    }
    bool dwell_slot = w.has_g(GCode::g4) && !w.dwell_direct.v;
    if (dwell_slot && (is_digit(ch) || ch == '.' || ch == '[' || ch == '-' || ch == '+' ||
                       (looks_like_lvalue(c) && c.s.find('=', c.pos) == std::string_view::npos))) {
      double v = 0;
      if (!eval_value(c, b.x, v)) return false;
      w.dwell_direct.set(v, pos);
      ++w.word_count;
      continue;
    }
    if (looks_like_lvalue(c)) {
      if (!parse_assignment(c, b, w)) return false;
      continue;
    }
    if (ch == '@') {
      if (!parse_cycle_word(c, b, w)) return false;
      continue;
    }
    if (ch == 'S') {
      if (!parse_spindle_word(c, b, w)) return false;
      ++w.word_count;
      continue;
    }
    if (is_alpha(ch)) {
      if (!parse_letter_word(c, b, w)) return false;
      continue;
    }
    if (static_cast<unsigned char>(ch) < 32 || static_cast<unsigned char>(ch) > 126)
      return b.x.err.fail(ErrorId::NcUnexpectedCharacter, pos,
                          fmt::format("unexpected byte 0x{:02X}; the block must be plain text",
                                      static_cast<unsigned char>(ch)));
    return b.x.err.fail(ErrorId::NcUnexpectedCharacter, pos,
                        fmt::format("unexpected '{}': a word address letter is expected here", ch));
  }
  return true;
}

}  // namespace nck::nc::detail
