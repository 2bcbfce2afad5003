// An axis word's dimension and an axis programmed twice (TF5200 P-CHAN-00116
// multi_dimension_in_block, P-CHAN-00148 multi_axes_in_block, diagnosis
// 20203). By default G90/G91 act on the whole block and an axis may be
// programmed once. With P-CHAN-00116 a G90/G91 acts on the positions after
// it; nck's Block carries one dimension, so it takes such a block when all
// its positions get the dimension the block ends with, and refuses the rest
// by name. With P-CHAN-00148 as well, an axis may be programmed several
// times: under G90 the last value counts, under G91 they add up.
#include <bit>
#include <fmt/format.h>

#include "block_words.hpp"

namespace nck::nc::detail {
namespace {

// Bits of Words::axis_dims, indices of Words::axis_dim_pos.
enum DimSource : std::uint8_t { kDimInherited = 0, kDimAbsolute = 1, kDimIncremental = 2 };

// The dimension the G90/G91 written so far give the next position.
DimSource dimension_here(const Words& w) {
  for (std::size_t i = w.g.size(); i-- > 0;) {
    if (w.g[i].code == GCode::g90) return kDimAbsolute;
    if (w.g[i].code == GCode::g91) return kDimIncremental;
  }
  return kDimInherited;
}

void note_dimension(Words& w, std::size_t pos) {
  const DimSource d = dimension_here(w);
  const auto bit = static_cast<std::uint8_t>(1u << d);
  if (!(w.axis_dims & bit)) w.axis_dim_pos[d] = static_cast<std::uint32_t>(pos);
  w.axis_dims |= bit;
}

bool absolute_after(const Words& w, bool before) {
  for (const auto& g : w.g) {
    if (g.code == GCode::g90) before = true;
    if (g.code == GCode::g91) before = false;
  }
  return before;
}

const char* dimension_name(bool absolute) { return absolute ? "absolute (G90)" : "incremental (G91)"; }

}  // namespace

bool add_axis_word(BlockCtx& b, Words& w, int j, double v, std::size_t pos, std::string_view name) {
  const auto k = static_cast<std::size_t>(j);
  note_dimension(w, pos);
  if (!w.axes[k]) {
    w.set_axis(k, v, pos);
    return true;
  }
  const std::string& axis = b.axis_upper[k];
  if (!b.cfg.multi_axes_in_block)
    return b.x.err.fail(ErrorId::NcAxisTwice, pos,
                        fmt::format("axis {}{} is programmed twice in this block; keep one (or allow it with "
                                    "multi_axes_in_block, P-CHAN-00148)",
                                    axis, iequals(axis, name) ? std::string() : fmt::format(" (as {})", name)));
  w.axes[k] = v;
  w.axis_sum[k] += v;
  w.axis_pos[k] = static_cast<std::uint32_t>(pos);
  w.axis_repeat_mask |= 1u << k;
  ++w.axis_count;
  ++w.word_count;
  return true;
}

bool check_dimensions(const Words& w, BlockCtx& b, const ModalState& before) {
  if (!b.cfg.multi_dimension_in_block || w.axis_dims == 0) return true;
  const bool block_absolute = absolute_after(w, before.absolute);
  for (const DimSource d : {kDimInherited, kDimAbsolute, kDimIncremental}) {
    if (!(w.axis_dims & (1u << d))) continue;
    const bool absolute = d == kDimInherited ? before.absolute : d == kDimAbsolute;
    if (absolute != block_absolute)
      return b.x.err.fail(ErrorId::NcUnsupported, w.axis_dim_pos[d],
                          fmt::format("with multi_dimension_in_block (P-CHAN-00116) this position is {} and the "
                                      "block ends {}: a block of mixed dimensions is an ISG function nck does not "
                                      "support; write G90/G91 before all positions of the block, or split it",
                                      dimension_name(absolute), dimension_name(block_absolute)));
  }
  return true;
}

void resolve_repeated_axes(Words& w, bool absolute) {
  if (absolute) return;  // the last value is in axes[] already
  for (std::uint32_t m = w.axis_repeat_mask; m != 0; m &= m - 1) {
    const auto j = static_cast<std::size_t>(std::countr_zero(m));
    w.axes[j] = w.axis_sum[j];
  }
}

}  // namespace nck::nc::detail
