#pragma once
// Handwheel and manual offsets in preparation: G201/G202 (manual mode on /
// off for axes), #GET MANUAL OFFSETS, and which axes carry the handwheel
// offset (the kernel adds it to axis j when bit j of
// PlannedCommand::manual_offset_axes is set).
#include <cstdint>

#include "nck/prep/lookahead_window.hpp"
#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

class ManualUnit {
 public:
  // The block's G201/G202 and #GET MANUAL OFFSETS.
  void plan(const nc::Block& b, PlannedCommand& c, std::size_t n_axes) const;
  // A motion block has been planned: the handwheel offset is an offset like
  // the others (seed 2.10, 2.2.6): a programmed axis leaves it out under
  // #SUPPRESS OFFSETS (all kinds or MANUAL) and inside #MCS, and takes it
  // back at its next absolute position.
  void moved(const nc::Block& b, frames::SuppressMask mask, const PlanContext& ctx);
  // Only motion commands change the handwheel share; the others carry it on.
  void stamp(PlannedBlock& out) const;

 private:
  std::uint32_t axes_ = ~0u;  // bit j: the kernel adds the handwheel offset to axis j
};

}  // namespace nck::prep
