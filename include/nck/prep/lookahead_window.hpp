#pragma once
// The look-ahead window of a channel's preparation: planned blocks wait here
// until `depth` later blocks are known, then leave for the command queue.
// This is where tool radius compensation (offset segments, corner
// intersections), the backward velocity pass and synchronisation points act
// on a span of upcoming blocks. Today's planning needs no look-ahead
// (depth 0: a block passes straight through); the type holds up to N.
// Setup side: never called from tick().
#include <cstddef>

#include "nck/core/fixed_vector.hpp"
#include "nck/core/ring_buffer.hpp"
#include "nck/kernel/queues.hpp"

namespace nck::prep {

// The commands one block planned into.
using PlannedBlock = FixedVector<kernel::Command, kernel::kMaxCommandsPerBlock>;

template <std::size_t N>
class LookAheadWindow {
  static_assert(N > 0);

 public:
  // setup: how many blocks stay behind a block before it leaves (< N).
  explicit LookAheadWindow(std::size_t depth = 0) : depth_(depth < N ? depth : N - 1) {}

  std::size_t depth() const { return depth_; }
  std::size_t size() const { return blocks_.size(); }
  bool full() const { return blocks_.full(); }
  bool push(const PlannedBlock& b) { return blocks_.push(b); }

  // Hands the blocks that have `depth` successors (all of them when
  // flushing) to q while q has room for a whole block. True when nothing
  // that should leave is left behind.
  bool release(kernel::CommandQueue& q, bool flush) {
    const std::size_t keep = flush ? 0 : depth_;
    while (blocks_.size() > keep) {
      const PlannedBlock& b = blocks_.front();
      if (q.free_slots() < b.size()) return false;
      for (const kernel::Command& c : b) (void)q.push(c);  // fits: checked above
      blocks_.pop();
    }
    return true;
  }

 private:
  RingBuffer<PlannedBlock, N> blocks_;
  std::size_t depth_;
};

}  // namespace nck::prep
