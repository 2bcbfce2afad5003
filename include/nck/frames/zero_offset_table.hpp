#pragma once
// The zero-offset table [ZERO] as given at setup (FCT-C2 §2.7, P-ZERO-00001..4):
// groups 0..96, group 0 = G53, 1..6 = G54..G59, 7.. only through G159=n.
#include <cstdint>
#include <expected>
#include <vector>

#include "nck/frames/types.hpp"

namespace nck::frames {

struct ZeroOffsetGroup {
  AxisValues offset_mm{};         // P-ZERO-00003 versch, converted to mm / deg
  std::uint32_t inactive_mask = 0;  // P-ZERO-00004 inaktiv: bit j = axis j ignored
};

// Setup-time data (may allocate); the chain copies the resolved values.
struct ZeroOffsetTable {
  static constexpr int kDefaultGroups = 97;
  bool g53_available = false;  // P-ZERO-00001 g53_verfuegbar
  int default_index = 0;       // P-ZERO-00002 default_index
  std::vector<ZeroOffsetGroup> groups = std::vector<ZeroOffsetGroup>(kDefaultGroups);

  // Offset values of group `index` with inactive axes at 0. Group 0 is all
  // zeros unless g53_available. Errors: negative index -> 20582 (value
  // outside the data format), index past the table -> 20149.
  std::expected<AxisValues, FrameError> resolve(int index) const;
};

// G53 -> 0, G54..G59 -> 1..6 (the G159 index of a G code).
constexpr int zero_index_of_g(int g_number) { return g_number == 53 ? 0 : g_number - 53; }

}  // namespace nck::frames
