#pragma once
// The live snapshot lives in the run layer (nck/run/live_snapshot.hpp):
// the Python session fills one too, for the state document both show.
#include "nck/run/live_snapshot.hpp"

namespace nck::app::serve {
using app::channel_free;
using app::Lateness;
using app::LiveChannel;
using app::LiveSnapshot;
}  // namespace nck::app::serve
