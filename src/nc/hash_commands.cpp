// '#' commands: syntax and argument checks into the typed structs of
// hash_commands.hpp (facts sheet A, B, D). Execution is the kernel's.
#include "nck/nc/hash_commands.hpp"

#include <cmath>
#include <fmt/format.h>

#include "hash_parse_util.hpp"

namespace nck::nc {
namespace detail {
namespace {

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

// "[<int>]" -> value
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

bool known_name(const BlockCtx& b, const std::string& n) {
  if (find_axis(b, n) >= 0 || iequals(n, b.cfg.main_spindle_name)) return true;
  for (const auto& s : b.cfg.spindle_names)
    if (iequals(s, n)) return true;
  return false;
}

bool parse_pair(Cursor& c, BlockCtx& b, bool nbr, AxLinkPair& p) {
  std::size_t pos = c.pos;
  bool nested = c.match('[');
  p.slave = name_token(c);
  c.skip_spaces();
  if (!c.match('=')) return args_error(b, c.pos, "pair expected as <slave>=<master>");
  p.master = name_token(c);
  for (const auto* n : {&p.slave, &p.master}) {
    if (n->empty()) return args_error(b, pos, "axis or spindle name missing in the pair");
    if (nbr) {
      for (char ch : *n)
        if (!is_digit(ch)) return args_error(b, pos, fmt::format("NBR needs logical axis numbers, not {}", *n));
    } else if (!known_name(b, *n)) {
      return args_error(b, pos, fmt::format("{} is not an axis or spindle of this channel", *n));
    }
  }
  if (p.slave == p.master) return args_error(b, pos, "slave and master must differ");
  if (!nested) return true;
  c.skip_spaces();
  if (c.match(',')) {
    c.skip_spaces();
    if (c.match_keyword("G")) {
      p.gantry = true;
      double v = 0;
      c.skip_spaces();
      if (c.match(',')) {
        if (!eval_expr(c, b.x, v)) return false;
        p.limit1_mm = v;
        c.skip_spaces();
        if (!c.match(',')) return args_error(b, c.pos, "gantry needs both limits");
        if (!eval_expr(c, b.x, v)) return false;
        p.limit2_mm = v;
      }
    } else {
      double num = 0, den = 0;
      if (!eval_expr(c, b.x, num)) return false;
      c.skip_spaces();
      if (!c.match(',')) return args_error(b, c.pos, "scaling needs numerator and denominator");
      if (!eval_expr(c, b.x, den)) return false;
      if (den == 0) return b.x.err.fail(ErrorId::NcDivisionByZero, pos, "coupling denominator is 0");
      p.numerator = num;
      p.denominator = den;
    }
  }
  c.skip_spaces();
  if (!c.match(']')) return args_error(b, c.pos, "']' expected after the coupling pair");
  return true;
}

bool parse_link_def(Cursor& c, BlockCtx& b, bool nbr, HashCommand& out) {
  SetAxLink s;
  s.by_number = nbr;
  c.skip_spaces();
  if (!c.match('[')) return args_error(b, c.pos, "[<group>, <slave>=<master>, ...] expected");
  std::size_t gpos = c.pos;
  if (!int_arg(c, b, s.group, 0, 1000, "coupling group")) return false;
  if (s.group == 0)
    return args_error(b, gpos, "group 0 is defined by the channel parameters and cannot be redefined");
  for (;;) {
    c.skip_spaces();
    if (c.match(']')) break;
    if (!c.match(',')) return args_error(b, c.pos, "',' or ']' expected in the coupling list");
    c.skip_spaces();
    AxLinkPair p;
    if (!parse_pair(c, b, nbr, p)) return false;
    s.pairs.push_back(std::move(p));
  }
  if (s.pairs.empty()) return args_error(b, gpos, "a coupling group needs at least one pair");
  out = std::move(s);
  return true;
}

bool optional_group(Cursor& c, BlockCtx& b, std::optional<int>& g) {
  c.skip_spaces();
  if (c.peek() != '[') return true;
  int v = 0;
  if (!bracket_int(c, b, v, 0, 1000, "coupling group")) return false;
  g = v;
  return true;
}

// [a, b, ...] with up to n expressions, empty = 0.
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

bool parse_cs(Cursor& c, BlockCtx& b, bool acs, HashCommand& out) {
  CoordSystem cs;
  cs.acs = acs;
  c.skip_spaces();
  std::size_t pos = c.pos;
  auto read_values = [&]() {
    double v[6];
    int n = 0;
    if (!value_list(c, b, v, 6, n)) return false;
    for (int i = 0; i < n; ++i) cs.values[i] = v[i];
    cs.has_values = true;
    return true;
  };
  if (c.match_keyword("DEF") || c.match_keyword("ON")) {
    bool def = iequals(c.s.substr(pos, 3), "DEF");
    cs.op = def ? CsOp::def : CsOp::on;
    c.skip_spaces();
    if (c.peek() == '[') {
      // One bracket with one number: an id; several numbers: values.
      std::size_t open = c.pos;
      double v[6];
      int n = 0;
      if (!value_list(c, b, v, 6, n)) return false;
      c.skip_spaces();
      if (n == 1 && c.peek() != '[' && !def) {
        c.pos = open;
        int id = 0;
        if (!bracket_int(c, b, id, 1, 5, "coordinate system id")) return false;
        cs.id = id;
      } else if (n == 1 && c.peek() == '[') {
        c.pos = open;
        int id = 0;
        if (!bracket_int(c, b, id, 1, 5, "coordinate system id")) return false;
        cs.id = id;
        if (!read_values()) return false;
      } else {
        for (int i = 0; i < n; ++i) cs.values[i] = v[i];
        cs.has_values = true;
      }
    }
    if (def && !cs.has_values)
      return args_error(b, pos, "#CS/#ACS DEF needs the values [v1,v2,v3,a1,a2,a3]");
  } else if (c.match_keyword("OFF")) {
    cs.op = keywords(c, {"ALL"}) ? CsOp::off_all : CsOp::off;
  } else if (!acs && (c.match_keyword("ADD") || c.match_keyword("SELECT"))) {
    bool add = iequals(c.s.substr(pos, 3), "ADD");
    cs.op = add ? CsOp::add : CsOp::select;
    c.skip_spaces();
    if (!c.match('[')) return args_error(b, c.pos, "[<name>] expected");
    cs.name = name_token(c);
    c.skip_spaces();
    if (!c.match(']') || cs.name.empty() || cs.name.size() > 8)
      return args_error(b, pos, "the CS name must have 1..8 characters, in [ ]");
    bool reserved = cs.name == "ACS" || cs.name == "MCS" || cs.name == "IMCS";
    if (add && reserved) return args_error(b, pos, fmt::format("{} is a reserved name", cs.name));
    if (add && !read_values()) return false;
  } else if (!acs && c.match_keyword("MODE")) {
    c.skip_spaces();
    if (c.match_keyword("OFF")) {
      cs.op = CsOp::mode_off;
    } else if (c.match_keyword("ON")) {
      cs.op = CsOp::mode_on;
      c.skip_spaces();
      if (c.match('[')) {
        std::size_t e = c.s.find(']', c.pos);
        if (e == std::string_view::npos) return args_error(b, c.pos, "']' expected");
        cs.mode_option = to_upper(c.s.substr(c.pos, e - c.pos));
        c.pos = e + 1;
      }
    } else {
      return args_error(b, c.pos, "#CS MODE needs ON or OFF");
    }
  } else {
    return args_error(b, pos, fmt::format("#{} needs DEF, ON, OFF{}", acs ? "ACS" : "CS",
                                          acs ? "" : ", ADD, SELECT or MODE"));
  }
  out = std::move(cs);
  return true;
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

bool parse_rotation(Cursor& c, BlockCtx& b, HashCommand& out) {
  Rotation r;
  c.skip_spaces();
  if (c.match_keyword("OFF")) { r.on = false; out = r; return true; }
  if (!c.match_keyword("ON")) return args_error(b, c.pos, "#ROTATION needs ON or OFF");
  c.skip_spaces();
  if (c.match('[')) {
    for (;;) {
      c.skip_spaces();
      if (c.match(']')) break;
      std::size_t kp = c.pos;
      std::string key = to_upper(c.read_ident());
      c.skip_spaces();
      double v = 0;
      if (key.empty() || !c.match('=') || !eval_expr(c, b.x, v))
        return b.x.err.failed() ? false : args_error(b, kp, "ANGLE=, CENTER1= or CENTER2= expected");
      if (key == "ANGLE") r.angle_deg = v;
      else if (key == "CENTER1") r.center1_mm = v;
      else if (key == "CENTER2") r.center2_mm = v;
      else return args_error(b, kp, fmt::format("{} is not a #ROTATION option", key));
      c.skip_spaces();
      c.match(',');
    }
  }
  out = r;
  return true;
}

bool parse_suppress(Cursor& c, BlockCtx& b, HashCommand& out) {
  SuppressOffsets s;
  c.skip_spaces();
  if (c.match('[')) {
    s.all = false;
    for (;;) {
      c.skip_spaces();
      if (c.match(']')) break;
      std::size_t kp = c.pos;
      std::string k = to_upper(c.read_ident());
      if (k == "ZERO") s.zero = true;
      else if (k == "ADD_ZERO") s.add_zero = true;
      else if (k == "PSET") s.pset = true;
      else if (k == "CLAMP") s.clamp = true;
      else if (k == "TOOL") s.tool = true;
      else if (k == "MEASURE") s.measure = true;
      else if (k == "MANUAL") s.manual = true;
      else return args_error(b, kp, "offset kinds: ZERO ADD_ZERO PSET CLAMP TOOL MEASURE MANUAL");
      c.skip_spaces();
      c.match(',');
    }
  }
  out = s;
  return true;
}

}  // namespace

bool parse_hash(Cursor& c, BlockCtx& b, Words& w, bool& exclusive) {
  std::size_t pos = c.pos;
  ++c.pos;
  w.hash_pos = static_cast<std::uint32_t>(pos);
  exclusive = true;
  HashCommand cmd = ExplSyn{};
  if (keywords(c, {"SET", "AX", "LINK"})) {
    if (!parse_link_def(c, b, false, cmd)) return false;
  } else if (keywords(c, {"AX", "LINK"})) {
    if (keywords(c, {"ON"})) {
      EnableAxLink e;
      if (!optional_group(c, b, e.group)) return false;
      cmd = e;
    } else if (keywords(c, {"OFF"})) {
      DisableAxLink d;
      d.all = keywords(c, {"ALL"});
      if (!d.all && !optional_group(c, b, d.group)) return false;
      cmd = d;
    } else {
      bool nbr = keywords(c, {"NBR"});
      if (!parse_link_def(c, b, nbr, cmd)) return false;
    }
  } else if (keywords(c, {"ENABLE", "AX", "LINK"})) {
    EnableAxLink e;
    if (!optional_group(c, b, e.group)) return false;
    cmd = e;
  } else if (keywords(c, {"DISABLE", "AX", "LINK"})) {
    DisableAxLink d;
    if (!optional_group(c, b, d.group)) return false;
    cmd = d;
  } else if (keywords(c, {"MAIN", "SPINDLE"})) {
    MainSpindle m;
    c.skip_spaces();
    if (c.match('[')) {
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
    }
    cmd = m;
  } else if (keywords(c, {"CAX"})) {
    CAxis a;
    c.skip_spaces();
    if (c.match_keyword("OFF")) {
      a.on = false;
    } else if (c.peek() == '[') {
      std::vector<std::string> names;
      if (!named_list(c, b, names, 2)) return false;
      if (names.size() == 2) {
        if (!iequals(names[0], b.cfg.main_spindle_name) && !iequals(names[0], b.main_target))
          return b.x.err.fail(ErrorId::NcCaxNotMainSpindle, pos,
                              fmt::format("{} is not the main spindle; use #MAIN SPINDLE [{}] first", names[0], names[0]));
        a.spindle = names[0];
        a.axis = names[1];
      } else {
        a.axis = names[0];
      }
    }
    cmd = a;
  } else if (keywords(c, {"FACE"})) {
    Face f;
    c.skip_spaces();
    if (c.match_keyword("OFF")) {
      f.on = false;
    } else {
      if (c.peek_keyword("2ROT")) return b.x.err.fail(ErrorId::NcUnsupported, c.pos, "#FACE 2ROT is not supported");
      std::vector<std::string> names;
      if (!named_list(c, b, names, 2)) return false;
      if (names.size() != 2) return args_error(b, pos, "#FACE needs [<1st axis>, <2nd axis>]");
      f.axis1 = names[0];
      f.axis2 = names[1];
    }
    cmd = f;
  } else if (keywords(c, {"CYL"})) {
    Cylinder y;
    c.skip_spaces();
    if (c.match_keyword("OFF")) {
      y.on = false;
    } else {
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
    }
    cmd = y;
  } else if (keywords(c, {"EXPL", "SYN"})) {
    cmd = ExplSyn{};
  } else if (keywords(c, {"TOOL"})) {
    ToolData t;
    if (keywords(c, {"PREP"})) t.prep = true;
    else if (!keywords(c, {"DATA"})) return args_error(b, c.pos, "#TOOL needs DATA or PREP");
    double v[3];
    int n = 0;
    if (!value_list(c, b, v, 3, n)) return false;
    for (int i = 0; i < n; ++i) {
      if (v[i] < 0 || v[i] != std::round(v[i]) || v[i] > 1e9)
        return b.x.err.fail(ErrorId::NcBadToolNumber, pos, "tool fields must be integers >= 0");
      t.fields[i] = static_cast<std::int64_t>(v[i]);
    }
    t.count = n;
    cmd = t;
  } else if (keywords(c, {"CS"})) {
    if (!parse_cs(c, b, false, cmd)) return false;
  } else if (keywords(c, {"ACS"})) {
    if (!parse_cs(c, b, true, cmd)) return false;
  } else if (keywords(c, {"ECS"})) {
    c.skip_spaces();
    if (c.match_keyword("ON")) cmd = Ecs{true};
    else if (c.match_keyword("OFF")) cmd = Ecs{false};
    else if (c.peek_keyword("DEF"))
      return b.x.err.fail(ErrorId::NcEcsDef, pos, "#ECS DEF is not possible; use #ECS ON / #ECS OFF");
    else return args_error(b, c.pos, "#ECS needs ON or OFF");
  } else if (keywords(c, {"MCS"})) {
    c.skip_spaces();
    Mcs m;
    if (c.match_keyword("ON")) {
      c.skip_spaces();
      if (c.match('[')) {
        if (!keywords(c, {"EX", "TOOL"})) return args_error(b, c.pos, "#MCS ON [EX TOOL] expected");
        c.skip_spaces();
        if (!c.match(']')) return args_error(b, c.pos, "']' expected");
        m.ex_tool = true;
      }
    } else if (c.match_keyword("OFF")) {
      m.on = false;
    } else {
      return args_error(b, c.pos, "#MCS needs ON or OFF");
    }
    cmd = m;
  } else if (keywords(c, {"ROTATION"})) {
    if (!parse_rotation(c, b, cmd)) return false;
  } else if (keywords(c, {"PSET"})) {
    cmd = PSet{};
    exclusive = false;
  } else if (keywords(c, {"PRESET"})) {
    cmd = PReset{};
    exclusive = false;
  } else if (keywords(c, {"TLC"})) {
    Tlc t;
    c.skip_spaces();
    if (c.match_keyword("OFF")) {
      t.on = false;
    } else if (c.match_keyword("ON")) {
      c.skip_spaces();
      if (c.match('[')) {
        if (!eval_expr(c, b.x, t.delta_mm)) return false;
        c.skip_spaces();
        if (!c.match(']')) return args_error(b, c.pos, "']' expected");
      }
    } else {
      return args_error(b, c.pos, "#TLC needs ON or OFF");
    }
    cmd = t;
  } else if (keywords(c, {"SUPPRESS", "OFFSETS"})) {
    if (!parse_suppress(c, b, cmd)) return false;
    exclusive = false;
  } else if (keywords(c, {"GET", "MANUAL", "OFFSETS"})) {
    cmd = GetManualOffsets{};
  } else if (keywords(c, {"DIST", "CTRL"})) {
    if (!parse_dist_ctrl(c, b, pos, cmd)) return false;
  } else if (keywords(c, {"TIME"})) {
    c.skip_spaces();
    double v = 0;
    if (!eval_value(c, b.x, v)) return false;
    if (v < 0) return b.x.err.fail(ErrorId::NcDwellOutOfRange, pos, "#TIME must be 0 s or more");
    w.time_s.set(v, pos);
    return true;
  } else if (keywords(c, {"MSG"}) || keywords(c, {"FLUSH"})) {
    b.x.err.warn(ErrorId::NcIgnoredCommand, pos, "this # command is accepted but has no effect in nck");
    c.pos = c.s.size();
    return true;
  } else {
    std::string name = to_upper(c.read_ident());
    return b.x.err.fail(ErrorId::NcUnknownHashCommand, pos,
                        fmt::format("#{} is not a # command nck knows", name));
  }
  w.hash = std::move(cmd);
  return true;
}

}  // namespace detail
}  // namespace nck::nc
