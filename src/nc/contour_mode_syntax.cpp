// #CONTOUR MODE: the parameters of corner blending (G61/G261). nck has the
// ISG's corner-deviation type only (DEV, the default type) with its
// PATH_DEV; ON/OFF in front of the bracket also switch blending on (G261)
// or off (G260), as the ISG short form does. The bracket is
// [<type> <parameters> <actions>]: without a type it is DEV's. The other
// types, parameters and actions are refused as what they are.
#include <span>
#include <string_view>

#include <fmt/format.h>

#include "hash_parse_util.hpp"

namespace nck::nc::detail {
namespace {

constexpr double kMaxPathDevMm = 10.0;
// The ISG's contouring types (TF5200 "#CONTOUR MODE", and the older
// AUTO_DEV / AUTO_VEL) and the actions at the contouring curve.
constexpr std::string_view kContourTypes[] = {"DEV", "DIST", "DIST_SOFT", "DIST_MASTER", "POS", "PTP", "AUTO_DEV", "AUTO_VEL"};
constexpr std::string_view kActions[] = {"PRE_ACTION", "INTER_ACTION", "POST_ACTION"};

bool one_of(std::string_view word, std::span<const std::string_view> list) {
  for (std::string_view w : list)
    if (w == word) return true;
  return false;
}

// A word of the bracket other than PATH_DEV, said as what it is.
std::string not_supported(const std::string& key) {
  if (key.empty()) return "PATH_DEV=<mm> expected";
  if (one_of(key, kContourTypes)) return fmt::format("contouring type {} must come first in the bracket", key);
  if (one_of(key, kActions)) return fmt::format("#CONTOUR MODE action {} is not supported", key);
  return fmt::format("#CONTOUR MODE parameter {} is not supported (only PATH_DEV)", key);
}

bool syntax_error(HashCtx& h, std::size_t pos, std::string msg) {
  return h.b.x.err.fail(ErrorId::KernelContourModeSyntax, pos, std::move(msg));
}

bool add_g(HashCtx& h, GCode code) {
  if (!h.w.g.push_back(GWord{code, static_cast<std::uint32_t>(h.pos), 0}))
    return syntax_error(h, h.pos, "too many G functions in the block");
  return true;
}

// PATH_DEV=<mm> after the mode.
bool parse_dev_params(HashCtx& h) {
  Cursor& c = h.c;
  for (;;) {
    c.skip_spaces();
    if (c.match(',')) continue;
    if (c.match(']')) return true;
    if (c.at_end()) return syntax_error(h, h.pos, "']' expected to close #CONTOUR MODE");
    const std::size_t kp = c.pos;
    const std::string key = to_upper(c.read_ident());
    if (key != "PATH_DEV") return syntax_error(h, kp, not_supported(key));
    c.skip_spaces();
    if (!c.match('=')) return syntax_error(h, kp, "PATH_DEV=<mm> expected");
    c.skip_spaces();
    double v = 0;
    if (!eval_value(c, h.b.x, v)) return false;
    if (!(v > 0 && v <= kMaxPathDevMm))
      return h.b.x.err.fail(ErrorId::KernelContourDevRange, kp,
                            fmt::format("PATH_DEV={} is outside (0, {}] mm", v, kMaxPathDevMm));
    h.w.contour_dev.set(v, kp);
  }
}

}  // namespace

bool parse_contour_mode(HashCtx& h) {
  Cursor& c = h.c;
  h.yields_command = false;
  if (keywords(c, {"OFF"})) return add_g(h, GCode::g260);
  if (keywords(c, {"ON"}) && !add_g(h, GCode::g261)) return false;
  c.skip_spaces();
  if (!c.match('[')) return c.at_end() ? true : syntax_error(h, c.pos, "'[' expected after #CONTOUR MODE");
  c.skip_spaces();
  Cursor type = c;
  const std::string word = to_upper(type.read_ident());
  if (one_of(word, kContourTypes)) {  // else DEV's parameters follow at once
    if (word != "DEV")
      return syntax_error(h, c.pos, fmt::format("contouring type {} is not supported (only DEV)", word));
    c = type;
  }
  return parse_dev_params(h);
}

}  // namespace nck::nc::detail
