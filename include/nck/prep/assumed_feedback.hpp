#pragma once
// Feedback from execution where nothing executes (block search, nck check):
// a block that needs it (ChannelPrep::needs_feedback: G100, #CAX, #GET
// MANUAL OFFSETS) gets what would be true had nothing moved — the probe
// switches at the programmed end (so a measurement offset is 0 and no
// "probe did not switch" error comes), C starts at 0, no manual offsets.
#include "nck/kernel/queues.hpp"
#include "nck/nc/block.hpp"
#include "nck/nc/decoder.hpp"
#include "nck/prep/planner.hpp"

namespace nck::prep {

kernel::Feedback assumed_feedback(const nc::Block& b, const Planner& planner);

// Hands feedback f to the planner and the decoder's variables.
void take_feedback(const kernel::Feedback& f, Planner& planner, nc::Decoder& decoder);

}  // namespace nck::prep
