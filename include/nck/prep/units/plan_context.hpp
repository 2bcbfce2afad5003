#pragma once
// What a preparation unit may read (and the planned position it may move):
// the Planner builds one per call and passes it to its units. Units own
// their technology's state; everything they share is here or goes through
// an explicit call the Planner makes (docs/architecture.md, "Preparation:
// technology units").
#include <cstddef>
#include <expected>
#include <string>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/motion/axis_vector.hpp"
#include "nck/nc/block.hpp"
#include "nck/prep/channel_frames.hpp"
#include "nck/prep/kernel_vocabulary.hpp"
#include "nck/prep/plan_store.hpp"

namespace nck::prep {

class AxisTable;

// Where the axes stand once everything planned so far has run.
struct PlannedPosition {
  motion::AxisVector pcs{};  // programmed position (program coordinates, radii)
  motion::AxisVector mcs{};  // machine position at the end of the last planned block
  // The program position read anew from the machine position (after a
  // change of coordinate system, a measurement, a coupling ...).
  void reread(const ChannelFrames& f) { pcs = f.to_pcs(mcs); }
};

struct PlanContext {
  const config::Machine& machine;
  const config::ChannelConfig& channel;
  PlanStore& store;
  std::size_t n_axes;
  const AxisTable& axes;
  ChannelFrames& frames;
  PlannedPosition& planned;

  // The channel axis called `name`, -1 when there is none.
  int axis_named(std::string_view name) const {
    for (std::size_t j = 0; j < n_axes; ++j)
      if (channel.axes[j].name == name) return static_cast<int>(j);
    return -1;
  }
};

// The one error convention of preparation: a unit returns the diagnostic,
// the Planner turns it into an error command (error_command.hpp).
using PlanResult = std::expected<void, Diagnostic>;

// A diagnostic of block b (its line; the file is the command's file_id).
inline std::unexpected<Diagnostic> block_error(ErrorId id, const nc::Block& b, std::string message) {
  return std::unexpected(make_diagnostic(id, SourceLoc{{}, b.line, 0}, std::move(message)));
}

}  // namespace nck::prep
