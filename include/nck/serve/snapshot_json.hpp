#pragma once
// The live state as the API and the stream send it (docs/api.md, "state").
#include <array>
#include <optional>
#include <nlohmann/json.hpp>

#include "nck/kernel/affine_map.hpp"
#include "nck/serve/live_snapshot.hpp"
#include "nck/sim/dry_run.hpp"

namespace nck::app::serve {

// Per channel, what the block events said of the block it runs: its
// program -> machine map (the positions in program coordinates) and the
// modal state after it.
struct BlockContext {
  kernel::AffineMap frame;
  std::optional<nc::ModalState> modal;
};
using ChannelFrames = std::array<BlockContext, config::kMaxChannels>;

// `run`: the run the snapshot belongs to (names of files and spindles).
nlohmann::ordered_json snapshot_json(const LiveSnapshot& s, const config::Machine& m, const sim::DryRun& run,
                                     const ChannelFrames& frames);

}  // namespace nck::app::serve
