// The dynamic weightings of the path axes as words: G131=, G133=, G134=,
// G233= carry one percentage; G130 and G132 take theirs from the block's
// axis words (G130 with S only is the main spindle's weighting). Every
// percentage is a finite number > 0; the limits that depend on the axes
// (a_w_max, tr_w_min) are preparation's (prep/units/dyn_weights.cpp).
#include <cmath>
#include <fmt/format.h>

#include "block_words.hpp"

namespace nck::nc::detail {
namespace {

bool bad_percent(double v) { return !std::isfinite(v) || !(v > 0); }

bool fail(BlockCtx& b, std::size_t pos, std::string msg) {
  return b.x.err.fail(ErrorId::NcDynWeighting, pos, std::move(msg));
}

}  // namespace

bool check_weightings(const Words& w, BlockCtx& b) {
  for (const GWord& g : w.g) {
    if (group_weight(g.code) && bad_percent(g.value))
      return fail(b, g.pos, fmt::format("G{}={} is not a weighting > 0 %", g_number(g.code), g.value));
    const bool per_axis = g.code == GCode::g130 || g.code == GCode::g132;
    if (!per_axis) continue;
    if (w.axis_count == 0 && (g.code == GCode::g132 || !w.s.v))
      return fail(b, g.pos, fmt::format("G{} needs the axes' weightings in %, e.g. G{} X70 Y80", g_number(g.code),
                                        g_number(g.code)));
    if (w.has_g(GCode::g130) && w.has_g(GCode::g132))
      return fail(b, g.pos, "G130 and G132 share the axis words: program them in separate blocks");
    const GCode group = g.code == GCode::g130 ? GCode::g131 : GCode::g133;
    if (w.axis_count > 0 && w.has_g(group))
      return fail(b, g.pos, fmt::format("G{} and G{} weight the same values: program one of them", g_number(g.code),
                                        g_number(group)));
    for (std::size_t i = 0; i < kMaxAxes; ++i)
      if (w.axes[i] && bad_percent(*w.axes[i]))
        return fail(b, w.axis_pos[i],
                    fmt::format("G{}: the weighting {} of an axis is not a number > 0 %", g_number(g.code), *w.axes[i]));
  }
  return true;
}

}  // namespace nck::nc::detail
