// '#' commands: syntax and argument checks into the typed structs of
// hash_commands.hpp (docs/nc-language.md, "# commands"). Execution is the kernel's.
// This file holds the keyword table, the shared argument helpers and the
// small families; couplings are in hash_links.cpp, the offset chain in
// hash_cs.cpp; a technology in a home of its own brings its command's
// keywords and parser (#DIST CTRL: src/distctrl/nc/dist_ctrl_syntax.cpp).
#include "nck/nc/hash_commands.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

#include "hash_parse_util.hpp"
#include "isg_refusals.hpp"
#include "nck/core/axis_name.hpp"

namespace nck::nc {
namespace detail {

bool int_arg(Cursor& c, BlockCtx& b, int& out, int lo, int hi, std::string_view what) {
  c.skip_spaces();
  std::size_t pos = c.pos;
  double v = 0;
  if (!eval_expr(c, b.x, v)) return false;
  double r = std::round(v);
  if (std::fabs(v - r) > 1e-9 || r < lo || r > hi)
    return args_error(b, pos, fmt::format("{} must be an integer {}..{}, not {}", what, lo, hi, v));
  out = static_cast<int>(r);
  return true;
}

bool bracket_int(Cursor& c, BlockCtx& b, int& out, int lo, int hi, std::string_view what) {
  c.skip_spaces();
  if (!c.match('[')) return args_error(b, c.pos, fmt::format("[{}] expected", what));
  if (!int_arg(c, b, out, lo, hi, what)) return false;
  c.skip_spaces();
  if (!c.match(']')) return args_error(b, c.pos, "']' expected");
  return true;
}

std::string name_token(Cursor& c) {
  c.skip_spaces();
  std::size_t b0 = c.pos;
  while (!c.at_end() && (is_ident_char(c.peek()))) ++c.pos;
  return to_upper(c.s.substr(b0, c.pos - b0));
}

bool value_list(Cursor& c, BlockCtx& b, double* vals, int n, int& count) {
  c.skip_spaces();
  if (!c.match('[')) return args_error(b, c.pos, "[..] value list expected");
  count = 0;
  for (;;) {
    c.skip_spaces();
    if (c.peek() == ',' || c.peek() == ']') {
      if (count >= n) return args_error(b, c.pos, fmt::format("at most {} values", n));
      vals[count++] = 0;
    } else {
      if (count >= n) return args_error(b, c.pos, fmt::format("at most {} values", n));
      if (!eval_expr(c, b.x, vals[count++])) return false;
      c.skip_spaces();
    }
    if (c.match(']')) return true;
    if (!c.match(',')) return args_error(b, c.pos, "',' or ']' expected in the value list");
  }
}

bool named_list(Cursor& c, BlockCtx& b, std::vector<std::string>& names, std::size_t max) {
  c.skip_spaces();
  if (!c.match('[')) return args_error(b, c.pos, "[..] expected");
  for (;;) {
    std::string n = name_token(c);
    if (n.empty()) return args_error(b, c.pos, "axis name expected");
    names.push_back(n);
    c.skip_spaces();
    if (c.match(']')) break;
    if (!c.match(',') || names.size() >= max) return args_error(b, c.pos, "',' or ']' expected");
  }
  return true;
}

namespace {

// --- spindle and spindle-as-axis transformations ---------------------------

// "[<name>]" or "[<logical axis number>]" of a configured spindle.
bool main_spindle_ref(Cursor& c, BlockCtx& b, MainSpindle& m) {
  c.skip_spaces();
  std::size_t np = c.pos;
  std::string n = name_token(c);
  bool numeric = !n.empty() && is_digit(n[0]);
  if (numeric) {
    m.log_axis_nr = std::atoi(n.c_str());
    const auto& nrs = b.cfg.spindle_log_axis_numbers;
    bool found = nrs.empty();
    for (std::size_t i = 0; i < nrs.size() && i < b.cfg.spindle_names.size(); ++i)
      if (nrs[i] == *m.log_axis_nr) { found = true; m.name = b.cfg.spindle_names[i]; }
    if (!found)
      return b.x.err.fail(ErrorId::NcUnknownSpindle, np, fmt::format("no spindle has logical axis number {}", n));
  } else {
    bool found = false;
    for (const auto& s : b.cfg.spindle_names)
      if (iequals(s, n)) { found = true; m.name = s; }
    if (!found)
      return b.x.err.fail(ErrorId::NcUnknownSpindle, np,
                          fmt::format("'{}' is not a configured spindle of this channel", n));
  }
  c.skip_spaces();
  if (!c.match(']')) return args_error(b, c.pos, "']' expected");
  return true;
}

bool parse_main_spindle(HashCtx& h) {
  MainSpindle m;
  h.c.skip_spaces();
  if (h.c.match('[') && !main_spindle_ref(h.c, h.b, m)) return false;
  h.cmd = m;
  return true;
}

// The C axis's name from here on: the one #CAX gives (a valid path-axis
// name no other axis has), else P-CHAN-00010's; #CAX OFF goes back to that.
bool name_c_axis(HashCtx& h, const CAxis& a) {
  BlockCtx& b = h.b;
  if (b.cfg.c_axis < 0 || static_cast<std::size_t>(b.cfg.c_axis) >= b.axis_upper.size())
    return true;  // no C axis: preparation says why (21184)
  std::string name = to_upper(a.on && !a.axis.empty() ? a.axis : b.cfg.c_axis_default_name);
  if (a.on && !a.axis.empty()) {
    const int other = find_axis(b, name);
    if (!valid_path_axis_name(name))
      return b.x.err.fail(ErrorId::KernelCaxBadAxes, h.pos,
                          fmt::format("#CAX: '{}' is no axis name (A, B, C, U, V, W, X, Y, Z or Q, then letters, "
                                      "digits and _)", a.axis));
    if (other >= 0 && other != b.cfg.c_axis)
      return b.x.err.fail(ErrorId::KernelCaxBadAxes, h.pos,
                          fmt::format("#CAX: {} is already a channel axis; give the C axis a name of its own", a.axis));
  }
  b.axis_upper[static_cast<std::size_t>(b.cfg.c_axis)] = std::move(name);
  return true;
}

bool parse_cax(HashCtx& h) {
  Cursor& c = h.c;
  BlockCtx& b = h.b;
  CAxis a;
  c.skip_spaces();
  if (c.match_keyword("OFF")) {
    a.on = false;
  } else if (c.peek() == '[') {
    std::vector<std::string> names;
    if (!named_list(c, b, names, 2)) return false;
    if (names.size() == 2) {
      if (!iequals(names[0], b.cfg.main_spindle_name) && !iequals(names[0], b.main_target))
        return b.x.err.fail(ErrorId::NcCaxNotMainSpindle, h.pos,
                            fmt::format("{} is not the main spindle; use #MAIN SPINDLE [{}] first", names[0], names[0]));
      a.spindle = names[0];
      a.axis = names[1];
    } else {
      a.axis = names[0];
    }
  }
  if (!name_c_axis(h, a)) return false;
  h.cmd = a;
  return true;
}

bool parse_face(HashCtx& h) {
  Cursor& c = h.c;
  BlockCtx& b = h.b;
  Face f;
  c.skip_spaces();
  if (c.match_keyword("OFF")) {
    f.on = false;
  } else {
    if (c.peek_keyword("2ROT"))
      return b.x.err.fail(ErrorId::NcUnsupported, c.pos, "#FACE 2ROT is an ISG function nck does not support");
    std::vector<std::string> names;
    if (!named_list(c, b, names, 2)) return false;
    if (names.size() != 2) return args_error(b, h.pos, "#FACE needs [<1st axis>, <2nd axis>]");
    f.axis1 = names[0];
    f.axis2 = names[1];
  }
  h.cmd = f;
  return true;
}

// "[<axis1>, <axis2>, <axis3><radius>]" after #CYL.
bool cylinder_args(Cursor& c, BlockCtx& b, std::size_t pos, Cylinder& y) {
  if (!c.match('[')) return args_error(b, c.pos, "#CYL needs [<axis1>, <axis2>, <axis3><radius>]");
  y.axis1 = name_token(c);
  c.skip_spaces();
  if (!c.match(',')) return args_error(b, c.pos, "',' expected");
  y.axis2 = name_token(c);
  c.skip_spaces();
  if (!c.match(',')) return args_error(b, c.pos, "',' expected");
  c.skip_spaces();
  std::size_t a0 = c.pos;
  while (is_alpha(c.peek())) ++c.pos;
  y.axis3 = to_upper(c.s.substr(a0, c.pos - a0));
  c.skip_spaces();
  c.match('=');
  double r = 0;
  if (y.axis1.empty() || y.axis2.empty() || y.axis3.empty() || !eval_value(c, b.x, r))
    return b.x.err.failed() ? false : args_error(b, pos, "#CYL needs [<axis1>, <axis2>, <axis3><radius>]");
  if (r <= 0) return args_error(b, a0, "the cylinder reference radius must be > 0");
  y.radius_mm = r;
  c.skip_spaces();
  if (!c.match(']')) return args_error(b, c.pos, "']' expected");
  return true;
}

bool parse_cyl(HashCtx& h) {
  Cylinder y;
  h.c.skip_spaces();
  if (h.c.match_keyword("OFF")) y.on = false;
  else if (h.c.peek_keyword("2ROT"))
    return h.b.x.err.fail(ErrorId::NcUnsupported, h.c.pos, "#CYL 2ROT is an ISG function nck does not support");
  else if (!cylinder_args(h.c, h.b, h.pos, y)) return false;
  h.cmd = y;
  return true;
}

// --- tool data --------------------------------------------------------------

bool parse_tool(HashCtx& h) {
  ToolData t;
  if (keywords(h.c, {"PREP"})) t.prep = true;
  else if (!keywords(h.c, {"DATA"})) return args_error(h.b, h.c.pos, "#TOOL needs DATA or PREP");
  double v[3];
  int n = 0;
  if (!value_list(h.c, h.b, v, 3, n)) return false;
  for (int i = 0; i < n; ++i) {
    if (v[i] < 0 || v[i] != std::round(v[i]) || v[i] > 1e9)
      return h.b.x.err.fail(ErrorId::NcBadToolNumber, h.pos, "tool fields must be integers >= 0");
    t.fields[i] = static_cast<std::int64_t>(v[i]);
  }
  t.count = n;
  h.cmd = t;
  return true;
}

// --- commands without arguments, and those that yield no command -----------

bool parse_expl_syn(HashCtx& h) {
  h.cmd = ExplSyn{};
  return true;
}

// PSET / PRESET take the axis positions programmed in the same block.
bool parse_pset(HashCtx& h) {
  h.cmd = PSet{};
  h.exclusive = false;
  return true;
}

bool parse_preset(HashCtx& h) {
  h.cmd = PReset{};
  h.exclusive = false;
  return true;
}

bool parse_get_manual_offsets(HashCtx& h) {
  h.cmd = GetManualOffsets{};
  return true;
}

// #TIME is a dwell: a word of the block, not a # command of its own.
bool parse_time(HashCtx& h) {
  h.yields_command = false;
  h.c.skip_spaces();
  double v = 0;
  if (!eval_value(h.c, h.b.x, v)) return false;
  if (v < 0) return h.b.x.err.fail(ErrorId::NcDwellOutOfRange, h.pos, "#TIME must be 0 s or more");
  h.w.time_s.set(v, h.pos);
  return true;
}

bool parse_ignored(HashCtx& h) {
  h.yields_command = false;
  h.b.x.err.warn(ErrorId::NcIgnoredCommand, h.pos, "this # command is accepted but has no effect in nck");
  h.c.pos = h.c.s.size();
  return true;
}

// The # commands by their keywords, tried in this order: a phrase must come
// before a shorter one it starts with (SET AX LINK before AX LINK).
struct HashEntry {
  std::array<std::string_view, 3> words;  // unused ones empty
  bool (*parse)(HashCtx&);
};

constexpr HashEntry kHashCommands[] = {
    {{"SET", "AX", "LINK"}, parse_set_ax_link},
    {{"SET", "SLOPE", "PROFIL"}, parse_set_slope_profil},
    {{"SLOPE"}, parse_slope},
    {{"AX", "LINK"}, parse_ax_link},
    {{"ENABLE", "AX", "LINK"}, parse_enable_ax_link},
    {{"DISABLE", "AX", "LINK"}, parse_disable_ax_link},
    {{"MAIN", "SPINDLE"}, parse_main_spindle},
    {{"CAX"}, parse_cax},
    {{"FACE"}, parse_face},
    {{"CYL"}, parse_cyl},
    {{"EXPL", "SYN"}, parse_expl_syn},
    {{"TOOL"}, parse_tool},
    {{"CS"}, parse_cs},
    {{"ACS"}, parse_acs},
    {{"ECS"}, parse_ecs},
    {{"MCS"}, parse_mcs},
    {{"ROTATION"}, parse_rotation},
    {{"PSET"}, parse_pset},
    {{"PRESET"}, parse_preset},
    {{"TLC"}, parse_tlc},
    {{"SUPPRESS", "OFFSETS"}, parse_suppress_offsets},
    {{"GET", "MANUAL", "OFFSETS"}, parse_get_manual_offsets},
    {{"TIME"}, parse_time},
    {{"CONTOUR", "MODE"}, parse_contour_mode},
    {{"MSG"}, parse_ignored},
    {{"FLUSH"}, parse_ignored},
};

// A technology's command (one with kKeywords, in a home of its own) when
// its keywords follow; *parsed false after a diagnostic. Tried after the
// table, in HashCommand's order.
template <std::size_t I = 0>
bool technology_command(HashCtx& h, bool& parsed) {
  if constexpr (I == std::variant_size_v<HashCommand>) {
    return false;
  } else {
    using Command = std::variant_alternative_t<I, HashCommand>;
    if constexpr (requires { Command::kKeywords; }) {
      if (keywords(h.c, Command::kKeywords)) {
        Command cmd;
        parsed = parse_hash_command(h, cmd);
        h.cmd = std::move(cmd);
        return true;
      }
    }
    return technology_command<I + 1>(h, parsed);
  }
}

}  // namespace

bool parse_hash(Cursor& c, BlockCtx& b, Words& w, bool& exclusive) {
  const std::size_t pos = c.pos;
  ++c.pos;
  w.hash_pos = static_cast<std::uint32_t>(pos);
  exclusive = true;
  const auto take = [&](HashCtx& h) {
    exclusive = h.exclusive;
    if (h.yields_command) w.hash = std::move(h.cmd);
    return true;
  };
  // Before the table: an ISG function may start like one nck has (#TOOL ORI).
  if (std::string fn = unsupported_hash(c); !fn.empty())
    return b.x.err.fail(ErrorId::NcUnsupported, pos, fmt::format("{} is an ISG function nck does not support", fn));
  for (const HashEntry& e : kHashCommands) {
    if (!keywords(c, e.words)) continue;
    HashCtx h{c, b, w, pos};
    if (!e.parse(h)) return false;
    return take(h);
  }
  HashCtx tech{c, b, w, pos};
  bool parsed = false;
  if (technology_command(tech, parsed)) return parsed && take(tech);
  std::string name = to_upper(c.read_ident());
  return b.x.err.fail(ErrorId::NcUnknownHashCommand, pos, fmt::format("#{} is not a # command nck knows", name));
}

}  // namespace detail
}  // namespace nck::nc
