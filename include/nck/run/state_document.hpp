#pragma once
// The state document: one writer for nck serve's GET /api/v1/state, its
// stream's state frames (the HMI reads them) and the Python session's
// Session.state() (issue 47 item 5; docs/api.md, "The state").
#include <array>
#include <optional>
#include <span>

#include <nlohmann/json.hpp>

#include "nck/kernel/affine_map.hpp"
#include "nck/output/last_errors.hpp"
#include "nck/run/live_snapshot.hpp"
#include "nck/prep/run_records.hpp"

namespace nck::app {

// Per channel, what the block events said of the block it runs: its
// program -> machine map (the positions in program coordinates) and the
// modal state after it.
struct BlockContext {
  kernel::AffineMap frame;
  std::optional<nc::ModalState> modal;
  // The coordinate systems the program set (#ACS, #CS): the last `offset`
  // event of each kind, as an index of the run's offsets (RunRecords::offset).
  std::optional<std::uint32_t> acs_offset, cs_offset;
};
using ChannelFrames = std::array<BlockContext, config::kMaxChannels>;

// Takes a block event's map and modal state, and an #ACS / #CS offset
// event, into its channel's context (other events leave it).
void note_event(ChannelFrames& frames, const kernel::Event& e, const prep::RunRecords& run);

// Per channel, where it stands in program coordinates and its modal state.
struct ChannelPlace {
  motion::AxisVector pcs{};
  std::optional<nc::ModalState> modal;
};

// The document. `run`: the run the snapshot belongs to (names of files and
// spindles); `places`: one per channel of the snapshot; `errors`: the last
// errors (null fields without).
nlohmann::ordered_json state_json(const LiveSnapshot& s, const config::Machine& m, const prep::RunRecords& run,
                                  std::span<const ChannelPlace> places, const LastErrors* errors);

// Per channel of the snapshot, its place from the block events' maps.
std::array<ChannelPlace, config::kMaxChannels> channel_places(const LiveSnapshot& s, const config::Machine& m,
                                                             const ChannelFrames& frames);

// nck serve's: the places from the block events' maps.
nlohmann::ordered_json snapshot_json(const LiveSnapshot& s, const config::Machine& m, const prep::RunRecords& run,
                                     const ChannelFrames& frames, const LastErrors* errors = nullptr);

}  // namespace nck::app
