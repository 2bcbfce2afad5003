#pragma once
// The look-ahead window of a channel's preparation: planned commands wait
// here until `depth` later commands are known (P-CHAN-00653), then leave
// for the command queue with the velocity at their end decided.
//
// Velocity look-ahead: consecutive motions form a chain when nothing between
// them needs the path at standstill (an output or spindle function, a wait,
// a dwell, a stop, G60/G360 ...; see docs/decisions.md). Within a chain each
// transition may be passed at the planner's corner/feed limit, but never so
// fast that the blocks after it could not brake in time: the end of the
// window is taken as a stop (nothing later is known), and a backward pass
// lowers each transition to what the rest of the chain can absorb. Appending
// a block only ever raises earlier transitions, so a command that has left
// is never too fast; the pass stops at the first transition that does not
// change, which keeps the cost per block small.
//
// This is also where tool radius compensation will act on a span of
// upcoming blocks. Setup side: never called from tick().
#include <cstddef>
#include <cstdint>
#include <vector>

#include "nck/core/fixed_vector.hpp"
#include "nck/kernel/queues.hpp"

namespace nck::prep {

// The commands one block planned into.
using PlannedBlock = FixedVector<kernel::Command, kernel::kMaxCommandsPerBlock>;

class LookAheadWindow {
 public:
  // setup: depth = commands that stay behind a command before it leaves;
  // cycle_s = the kernel's cycle (its braking is discrete).
  explicit LookAheadWindow(std::size_t depth = 0, double cycle_s = 0.001);

  std::size_t depth() const { return depth_; }
  std::size_t size() const { return static_cast<std::size_t>(tail_ - head_); }
  bool empty() const { return head_ == tail_; }
  // Room for one more block without releasing first.
  bool has_room() const { return size() + kernel::kMaxCommandsPerBlock <= ring_.size(); }
  // Appends a block's commands (false when there is no room: release first).
  bool push(const PlannedBlock& b);

  // Hands the commands that have `depth` successors (all of them when
  // flushing) to q while it has room. True when nothing that should leave
  // is left behind.
  bool release(kernel::CommandQueue& q, bool flush);

 private:
  struct Entry {
    kernel::Command command;
    std::uint64_t prev_motion = 0;  // sequence number + 1 of the motion chained before, 0 = none
    double end_cap_mm_s = 0;        // corner/feed limit at its end while chained, else 0
  };
  Entry& at(std::uint64_t seq) { return ring_[seq % ring_.size()]; }
  void append(const kernel::Command& c);
  void raise_chain(std::uint64_t next);
  double entry_limit(const kernel::Command& c) const;

  std::vector<Entry> ring_;
  std::uint64_t head_ = 0, tail_ = 0;  // sequence numbers: [head_, tail_) are in the window
  std::size_t depth_;
  double cycle_s_;
  std::uint64_t open_motion_ = 0;  // sequence number + 1 of a motion whose end may still blend
  bool late_wait_pending_ = false;  // an MVS_SLM function waits at the next feed motion
};

}  // namespace nck::prep
