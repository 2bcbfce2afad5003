// # commands of the offset chain (FCT-C2 §2; docs/nc-language.md): coordinate systems, the
// rotation, suppressed offsets and the tool length correction.
#include <fmt/format.h>

#include "hash_parse_util.hpp"

namespace nck::nc::detail {
namespace {

bool parse_coord_system(Cursor& c, BlockCtx& b, bool acs, HashCommand& out) {
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

bool parse_rotation_args(Cursor& c, BlockCtx& b, HashCommand& out) {
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

bool parse_suppressed_kinds(Cursor& c, BlockCtx& b, HashCommand& out) {
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

bool parse_cs(HashCtx& h) { return parse_coord_system(h.c, h.b, false, h.cmd); }
bool parse_acs(HashCtx& h) { return parse_coord_system(h.c, h.b, true, h.cmd); }
bool parse_rotation(HashCtx& h) { return parse_rotation_args(h.c, h.b, h.cmd); }

bool parse_suppress_offsets(HashCtx& h) {
  if (!parse_suppressed_kinds(h.c, h.b, h.cmd)) return false;
  h.exclusive = false;  // suppresses the offsets for the motion in this block
  return true;
}

bool parse_ecs(HashCtx& h) {
  Cursor& c = h.c;
  c.skip_spaces();
  if (c.match_keyword("ON")) h.cmd = Ecs{true};
  else if (c.match_keyword("OFF")) h.cmd = Ecs{false};
  else if (c.peek_keyword("DEF"))
    return h.b.x.err.fail(ErrorId::NcEcsDef, h.pos, "#ECS DEF is not possible; use #ECS ON / #ECS OFF");
  else return args_error(h.b, c.pos, "#ECS needs ON or OFF");
  return true;
}

bool parse_mcs(HashCtx& h) {
  Cursor& c = h.c;
  c.skip_spaces();
  Mcs m;
  if (c.match_keyword("ON")) {
    c.skip_spaces();
    if (c.match('[')) {
      if (!keywords(c, {"EX", "TOOL"})) return args_error(h.b, c.pos, "#MCS ON [EX TOOL] expected");
      c.skip_spaces();
      if (!c.match(']')) return args_error(h.b, c.pos, "']' expected");
      m.ex_tool = true;
    } else if (c.peek_keyword("EX")) {  // the option without its brackets
      return args_error(h.b, c.pos, "the option of #MCS ON stands in brackets: #MCS ON [EX TOOL]");
    }
  } else if (c.match_keyword("OFF")) {
    m.on = false;
  } else {
    return args_error(h.b, c.pos, "#MCS needs ON or OFF");
  }
  h.cmd = m;
  return true;
}

bool parse_tlc(HashCtx& h) {
  Cursor& c = h.c;
  Tlc t;
  c.skip_spaces();
  if (c.match_keyword("OFF")) {
    t.on = false;
  } else if (c.match_keyword("ON")) {
    c.skip_spaces();
    if (c.match('[')) {
      if (!eval_expr(c, h.b.x, t.delta_mm)) return false;
      c.skip_spaces();
      if (!c.match(']')) return args_error(h.b, c.pos, "']' expected");
    }
  } else {
    return args_error(h.b, c.pos, "#TLC needs ON or OFF");
  }
  h.cmd = t;
  return true;
}

}  // namespace nck::nc::detail
