#include "nck/frames/zero_offset_table.hpp"

namespace nck::frames {

std::expected<AxisValues, FrameError> ZeroOffsetTable::resolve(int index) const {
  if (index < 0) return std::unexpected(FrameError{ErrorId::NcZeroOffsetIndexInvalid, -1, index});
  if (static_cast<std::size_t>(index) >= groups.size())
    return std::unexpected(FrameError{ErrorId::NcZeroOffsetIndexTooLarge, -1, index});
  AxisValues out{};
  // G53 normally means "no zero offset"; only g53_available makes group 0 usable.
  if (index == 0 && !g53_available) return out;
  const ZeroOffsetGroup& g = groups[static_cast<std::size_t>(index)];
  for (std::size_t j = 0; j < kMaxAxes; ++j)
    out[j] = (g.inactive_mask >> j) & 1u ? 0.0 : g.offset_mm[j];
  return out;
}

}  // namespace nck::frames
