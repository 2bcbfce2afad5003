// # commands of the axis couplings (AX LINK groups; spindle_link seed, TF5200 #SET AX LINK).
#include <fmt/format.h>

#include "hash_parse_util.hpp"

namespace nck::nc::detail {
namespace {

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

}  // namespace

bool parse_set_ax_link(HashCtx& h) { return parse_link_def(h.c, h.b, false, h.cmd); }

bool parse_enable_ax_link(HashCtx& h) {
  EnableAxLink e;
  if (!optional_group(h.c, h.b, e.group)) return false;
  h.cmd = e;
  return true;
}

bool parse_disable_ax_link(HashCtx& h) {
  DisableAxLink d;
  if (!optional_group(h.c, h.b, d.group)) return false;
  h.cmd = d;
  return true;
}

bool parse_ax_link(HashCtx& h) {
  if (keywords(h.c, {"ON"})) return parse_enable_ax_link(h);
  if (keywords(h.c, {"OFF"})) {
    DisableAxLink d;
    d.all = keywords(h.c, {"ALL"});
    if (!d.all && !optional_group(h.c, h.b, d.group)) return false;
    h.cmd = d;
    return true;
  }
  const bool by_number = keywords(h.c, {"NBR"});
  return parse_link_def(h.c, h.b, by_number, h.cmd);
}

}  // namespace nck::nc::detail
