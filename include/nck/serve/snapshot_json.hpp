#pragma once
// The state document has one writer, in the run layer
// (nck/run/state_document.hpp), shared with the Python session.
#include "nck/run/state_document.hpp"
#include "nck/serve/live_snapshot.hpp"

namespace nck::app::serve {
using app::BlockContext;
using app::ChannelFrames;
using app::snapshot_json;
}  // namespace nck::app::serve
