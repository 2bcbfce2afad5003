// #SLOPE [TYPE=STEP|TRAPEZ|SIN2|HSC], #SLOPE DEFAULT and the older
// #SET SLOPE PROFIL[n]: the acceleration profile of the path motions after
// the block (modal; program start and #SLOPE DEFAULT take P-CHAN-00071).
// nck has the profile type only: the #SLOPE weighting parameters are
// refused by name (docs/decisions.md, "Jerk-limited slopes, HSC and
// dynamic weightings"), never silently ignored.
#include <fmt/format.h>

#include "hash_parse_util.hpp"
#include "nck/core/slope.hpp"

namespace nck::nc::detail {
namespace {

bool syntax_error(HashCtx& h, std::size_t pos, std::string msg) {
  return h.b.x.err.fail(ErrorId::NcSlopeSyntax, pos, std::move(msg));
}

bool set_slope(HashCtx& h, SlopeProfile p, std::size_t pos) {
  h.w.slope.set(p, pos);
  return true;
}

// TYPE=<name> inside the brackets; the name is a word, not an expression.
bool parse_type(HashCtx& h, std::size_t key_pos) {
  Cursor& c = h.c;
  c.skip_spaces();
  if (!c.match('=')) return syntax_error(h, key_pos, "TYPE=<STEP|TRAPEZ|SIN2|HSC> expected");
  c.skip_spaces();
  const std::size_t np = c.pos;
  const std::string name = to_upper(c.read_ident());
  const auto p = slope_from_name(name);
  if (!p)
    return h.b.x.err.fail(ErrorId::NcSlopeType, np,
                          fmt::format("#SLOPE TYPE={} is not a slope type (STEP, TRAPEZ, SIN2 or HSC)",
                                      name.empty() ? std::string("<nothing>") : name));
  return set_slope(h, *p, np);
}

}  // namespace

bool parse_slope(HashCtx& h) {
  Cursor& c = h.c;
  h.yields_command = false;
  if (keywords(c, {"DEFAULT"})) {
    h.w.slope_default = true;  // the weightings G130...G134, G233 go back to 100 % (prep)
    return set_slope(h, h.b.cfg.slope_default, h.pos);
  }
  c.skip_spaces();
  if (!c.match('[')) return syntax_error(h, c.pos, "'[' or DEFAULT expected after #SLOPE");
  bool typed = false;
  for (;;) {
    c.skip_spaces();
    if (c.match(',')) continue;
    if (c.match(']')) break;
    if (c.at_end()) return syntax_error(h, c.pos, "']' expected to close #SLOPE");
    const std::size_t kp = c.pos;
    const std::string key = to_upper(c.read_ident());
    if (key == "NO_OPT") {  // 1 (the default): no optimised use of jerk, which nck does not have anyway
      c.skip_spaces();
      if (!c.match('=')) return syntax_error(h, kp, "NO_OPT=<0|1> expected");
      int n = 1;
      if (!int_arg(c, h.b, n, 0, 1, "#SLOPE NO_OPT")) return false;
      if (n == 0)
        return syntax_error(h, kp, "#SLOPE NO_OPT=0 (optimised use of jerk) is not supported; NO_OPT=1 is the default");
      continue;
    }
    if (key != "TYPE")
      return syntax_error(h, kp, key.empty() ? std::string("TYPE=<STEP|TRAPEZ|SIN2|HSC> expected")
                                             : fmt::format("#SLOPE parameter {} is not supported (only TYPE)", key));
    if (!parse_type(h, kp)) return false;
    typed = true;
  }
  return typed ? true : syntax_error(h, h.pos, "#SLOPE [ ] names no TYPE");
}

bool parse_set_slope_profil(HashCtx& h) {
  Cursor& c = h.c;
  h.yields_command = false;
  c.skip_spaces();
  const std::size_t np = c.pos;
  int n = 0;
  if (!bracket_int(c, h.b, n, -1000000, 1000000, "slope profile")) return false;
  const auto p = slope_from_number(n);
  if (!p)
    return h.b.x.err.fail(ErrorId::NcSlopeType, np,
                          fmt::format("#SET SLOPE PROFIL[{}] is not a slope profile (0 ... 3)", n));
  return set_slope(h, *p, np);
}

}  // namespace nck::nc::detail
