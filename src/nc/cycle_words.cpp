// The @ words of cycle programming: a cycle is written once for any plane
// and any axis names. @X/@Y/@Z are the first, second and third main axis of
// the working plane (G17: X Y Z, G18: Z X Y, G19: Y Z X), @I/@J/@K their
// centre coordinates, @S the main spindle, @P<n> a transfer parameter of
// the call. All of them exist only inside a cycle (TF5200 21382 outside).
#include <fmt/format.h>

#include "block_words.hpp"

namespace nck::nc::detail {

namespace {

bool outside(BlockCtx& b, std::size_t pos, char what) {
  return b.x.err.fail(ErrorId::NcCycleParamOutsideCycle, pos,
                      fmt::format("@{} exists only inside a cycle (called with L CYCLE [..])", what));
}

// The value after @X..: blanks, an optional '=', then a word value.
bool at_value(Cursor& c, BlockCtx& b, double& v, char what) {
  c.skip_spaces();
  c.match('=');
  c.skip_spaces();
  if (c.at_end() || c.peek() == ';' || c.peek() == '(')
    return b.x.err.fail(ErrorId::NcBadValue, c.pos, fmt::format("@{} needs a value", what));
  return eval_value(c, b.x, v);
}

// @X/@Y/@Z (k = 0, 1, 2 of the plane's order) as a word of channel axis j.
bool main_axis_word(Cursor& c, BlockCtx& b, Words& w, std::size_t pos, int k, char what) {
  const PlaneAxes pa = plane_axes(b.plane);
  const int m = k == 0 ? pa.first : k == 1 ? pa.second : pa.tool;
  const int j = find_axis(b, kMainAxisNames[m]);
  if (j < 0)
    return b.x.err.fail(ErrorId::NcCycleAxisMissing, pos,
                        fmt::format("@{} is main axis {} in G{}, which this channel does not have", what,
                                    kMainAxisNames[m], static_cast<int>(b.plane)));
  double v = 0;
  return at_value(c, b, v, what) && add_axis_word(b, w, j, v, pos, fmt::format("@{}", what));
}

// @I/@J/@K: the centre coordinate that belongs to @X/@Y/@Z.
bool centre_word(Cursor& c, BlockCtx& b, Words& w, std::size_t pos, int k, char what) {
  const PlaneAxes pa = plane_axes(b.plane);
  const int m = k == 0 ? pa.first : k == 1 ? pa.second : pa.tool;
  double v = 0;
  if (!at_value(c, b, v, what)) return false;
  if (w.ijk[m].v)
    return b.x.err.fail(ErrorId::NcDuplicateWord, pos,
                        fmt::format("{} is programmed twice (@{})", static_cast<char>('I' + m), what));
  w.ijk[m].set(v, pos);
  ++w.word_count;
  return true;
}

}  // namespace

bool parse_cycle_word(Cursor& c, BlockCtx& b, Words& w) {
  const std::size_t pos = c.pos;
  const char what = upper(c.peek(1));
  const bool in_cycle = b.x.vars.in_cycle();
  switch (what) {
    case 'P': {  // @P<n> = <expr>: assignment (looks_like_lvalue handles it, this is a malformed one)
      return b.x.err.fail(ErrorId::NcCycleWord, pos, "@P needs a number: @P<n> = <value> (n = 1..200)");
    }
    case 'X': case 'Y': case 'Z':
      if (!in_cycle) return outside(b, pos, what);
      c.pos += 2;
      return main_axis_word(c, b, w, pos, what - 'X', what);
    case 'I': case 'J': case 'K':
      if (!in_cycle) return outside(b, pos, what);
      c.pos += 2;
      return centre_word(c, b, w, pos, what - 'I', what);
    case 'S':
      if (!in_cycle) return outside(b, pos, what);
      ++c.pos;  // the main spindle in DIN syntax, whatever its name
      ++w.word_count;
      return parse_spindle_word(c, b, w);
    default:
      return b.x.err.fail(ErrorId::NcCycleWord, pos,
                          "unknown @ word; a cycle knows @P<n>, @X @Y @Z, @I @J @K and @S");
  }
}

}  // namespace nck::nc::detail
