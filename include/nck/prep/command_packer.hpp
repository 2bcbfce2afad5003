#pragma once
// Planned commands leave the look-ahead window packed into the kernel's
// compact form (kernel/command.hpp): the header and the action into a
// Command, everything only some blocks carry into its attachments. A
// motion's start point goes along only when it is not, bit for bit, where
// the motion before it ended — the channel joins the segment back together
// (motion::Segment::joined), so it runs exactly the planned one.
#include "nck/kernel/queues.hpp"
#include "nck/motion/axis_vector.hpp"
#include "nck/prep/planned_command.hpp"

namespace nck::prep {

class CommandPacker {
 public:
  // Puts c into q; false when q has no room for it (nothing changes then).
  bool pack(const PlannedCommand& c, kernel::CommandQueue& q);

 private:
  motion::AxisVector last_end_{};  // where the last motion handed over ends
};

}  // namespace nck::prep
