#pragma once
// The live state as the API and the stream send it (docs/api.md, "state").
#include <array>
#include <nlohmann/json.hpp>

#include "nck/kernel/affine_map.hpp"
#include "nck/sim/dry_run.hpp"
#include "serve/live_snapshot.hpp"

namespace nck::app::serve {

// Per channel, the program -> machine map of the block it runs (from the
// block events), for the positions in program coordinates.
using ChannelFrames = std::array<kernel::AffineMap, config::kMaxChannels>;

// `run`: the run the snapshot belongs to (names of files and spindles).
nlohmann::ordered_json snapshot_json(const LiveSnapshot& s, const config::Machine& m, const sim::DryRun& run,
                                     const ChannelFrames& frames);

}  // namespace nck::app::serve
