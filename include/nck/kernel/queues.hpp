#pragma once
// The two queues between a channel's block preparation (setup side, nck/prep)
// and its cyclic executor (kernel::Channel):
//   commands  prep -> channel: planned, immutable commands, each with its
//             attachments (attachment.hpp) in a ring of their own;
//   feedback  channel -> prep: what execution found that decoding needs
//             (a G100 measuring result, the handwheel offsets at
//             #GET MANUAL OFFSETS), as typed records.
// Both are single-producer / single-consumer and lock-free, so preparation
// may run in a thread of its own (docs/decisions.md, "Preparation and
// look-ahead", threading contract).
#include <cstdint>
#include <span>

#include "nck/core/spsc_queue.hpp"
#include "nck/kernel/attachment.hpp"
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

// Attachments queued at most (docs/performance.md: the queue's memory), and
// per command (a block's 8 outputs and 16 spindle actions, its warnings,
// offset events and switches).
inline constexpr std::size_t kAttachmentQueueLength = 256;
inline constexpr std::size_t kMaxAttachments = 48;

// The commands of a channel and their attachments: one producer (its
// preparation), one consumer (the channel). A command's attachments go in
// before it and leave with it, so the front command's are always the first
// in their ring.
class CommandQueue {
 public:
  static constexpr std::size_t capacity() noexcept { return kCommandQueueLength; }

  // producer: c with its attachments (c.attachments must be a.size());
  // false when either ring has no room (nothing is put in then).
  bool push(const Command& c, std::span<const Attachment> a = {}) noexcept {
    if (commands_.free_slots() == 0 || attachments_.free_slots() < a.size()) return false;
    for (const Attachment& x : a) (void)attachments_.push(x);
    return commands_.push(c);
  }
  std::size_t free_slots() const noexcept { return commands_.free_slots(); }
  std::size_t free_attachment_slots() const noexcept { return attachments_.free_slots(); }

  // consumer
  bool empty() const noexcept { return commands_.empty(); }
  std::size_t size() const noexcept { return commands_.size(); }
  const Command& front() const noexcept { return commands_.front(); }
  const Command& at(std::size_t i) const noexcept { return commands_.at(i); }
  // Attachment i of the front command (i < front().attachments).
  const Attachment& attachment(std::size_t i) const noexcept { return attachments_.at(i); }
  // The front command leaves, and its attachments with it.
  void pop() noexcept {
    if (commands_.empty()) return;
    for (std::size_t i = 0; i < commands_.front().attachments; ++i) attachments_.pop();
    commands_.pop();
  }

 private:
  SpscQueue<Attachment, kAttachmentQueueLength> attachments_;
  SpscQueue<Command, kCommandQueueLength> commands_;
};

enum class FeedbackKind : std::uint8_t {
  measured,        // a G100 run ended: `measure`
  manual_offsets,  // #GET MANUAL OFFSETS ran: `manual_offsets_mm`
  c_axis,          // #CAX ran: the spindle's position is C's start, `c_axis_deg`
  stopped,         // a reset or an error ended the program: the path stands at `path_mcs_mm`
};

struct Feedback {
  FeedbackKind kind = FeedbackKind::measured;
  MeasureResult measure{};
  motion::AxisVector manual_offsets_mm{};
  double c_axis_deg = 0;
  motion::AxisVector path_mcs_mm{};
};

// Preparation holds further blocks back after each block that needs
// feedback, so at most one record is in flight per channel; the spare slots
// make an overflow impossible rather than unlikely.
using FeedbackQueue = SpscQueue<Feedback, 4>;

}  // namespace nck::kernel
