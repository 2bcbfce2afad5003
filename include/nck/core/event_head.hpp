#pragma once
// What every event of a run says before its payload: when, in which channel
// and at which block. Each technology's event payload (the variant in
// nck/kernel/event.hpp) and its JSON writer take it.
#include <cstdint>

#include "nck/core/block_ref.hpp"

namespace nck {

struct EventHead {
  double t_s = 0;            // cycle start
  std::uint8_t channel = 0;  // 1-based; 0: not a channel's (a machine event)
  BlockRef at{};             // the block the channel stood at (none for a machine event)

  // The channel's index (0-based); a machine event counts as the first channel's.
  std::size_t channel_index() const noexcept { return channel > 0 ? channel - 1u : 0u; }
};

}  // namespace nck
