#pragma once
// The two queues between a channel's block preparation (setup side, nck/prep)
// and its cyclic executor (kernel::Channel):
//   commands  prep -> channel: planned, immutable commands;
//   feedback  channel -> prep: what execution found that decoding needs
//             (a G100 measuring result, the handwheel offsets at
//             #GET MANUAL OFFSETS), as typed records.
// Both are single-producer / single-consumer and lock-free, so preparation
// may run in a thread of its own (docs/decisions.md, "threading contract").
#include <cstdint>

#include "nck/core/spsc_queue.hpp"
#include "nck/kernel/command.hpp"
#include "nck/kernel/measure.hpp"

namespace nck::kernel {

inline constexpr std::size_t kCommandQueueLength = 128;
// One block plans into at most this many commands (G74 homing: one per
// order group); preparation plans a block only when this many slots are free.
inline constexpr std::size_t kMaxCommandsPerBlock = 4;
// The look-ahead plans each block's end speed so that the path can stop
// within the commands that follow it in the window. The kernel trusts only
// what is queued (kernel/braking_reserve.hpp), so the window may look no
// further ahead than the queue holds: P-CHAN-00653 above this is capped.
inline constexpr std::size_t kMaxLookAheadDepth = kCommandQueueLength - 2 * kMaxCommandsPerBlock;

using CommandQueue = SpscQueue<Command, kCommandQueueLength>;

enum class FeedbackKind : std::uint8_t {
  measured,        // a G100 run ended: `measure`
  manual_offsets,  // #GET MANUAL OFFSETS ran: `manual_offsets_mm`
  c_axis,          // #CAX ran: the spindle's position is C's start, `c_axis_deg`
};

struct Feedback {
  FeedbackKind kind = FeedbackKind::measured;
  MeasureResult measure{};
  motion::AxisVector manual_offsets_mm{};
  double c_axis_deg = 0;
};

// Preparation holds further blocks back after each block that needs
// feedback, so at most one record is in flight per channel; the spare slots
// make an overflow impossible rather than unlikely.
using FeedbackQueue = SpscQueue<Feedback, 4>;

}  // namespace nck::kernel
