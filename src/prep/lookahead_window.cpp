#include "nck/prep/lookahead_window.hpp"

#include <algorithm>

#include "nck/motion/junction.hpp"

namespace nck::prep {
namespace {

using kernel::Command;
using kernel::CommandKind;
using kernel::SyncPoint;

// Nothing around it makes the channel wait or act at a block boundary: no
// output, spindle function, probing, manual mode or feedback. Only then can
// the path run through its ends.
bool is_quiet(const Command& c) {
  return c.outputs.empty() && c.spindle_actions.empty() && !c.measure && c.manual_on == 0 &&
         c.manual_off == 0 && !c.get_manual_offsets && !c.expl_syn;
}

// A block without motion the path may run through (it only writes events).
bool is_transparent(const Command& c) { return c.kind == CommandKind::nop && is_quiet(c); }

// An MVS_SLM function: the channel waits for it when the next G1/G2/G3 starts.
bool waits_at_next_feed_motion(const Command& c) {
  for (const kernel::Output& o : c.outputs)
    if (kernel::sync_point(o.sync) == SyncPoint::late_motion) return true;
  for (const kernel::SpindleAction& a : c.spindle_actions)
    if (a.sync == SyncPoint::late_motion) return true;
  return false;
}

}  // namespace

LookAheadWindow::LookAheadWindow(std::size_t depth, double cycle_s)
    : ring_(depth + 2 * kernel::kMaxCommandsPerBlock), depth_(depth), cycle_s_(cycle_s) {}

bool LookAheadWindow::push(const PlannedBlock& b) {
  if (!has_room()) return false;
  for (const Command& c : b) append(c);
  return true;
}

void LookAheadWindow::append(const Command& c) {
  const std::uint64_t seq = tail_++;
  Entry& e = at(seq);
  e.command = c;
  e.command.v_end_mm_s = 0;
  e.prev_motion = 0;
  e.end_cap_mm_s = 0;
  if (c.kind == CommandKind::motion) {
    const bool must_wait = late_wait_pending_ && c.feed_motion;
    const bool chained = open_motion_ != 0 && open_motion_ - 1 >= head_ && is_quiet(c) && !must_wait &&
                         c.v_entry_max_mm_s > 0;
    if (chained) {
      at(open_motion_ - 1).end_cap_mm_s = c.v_entry_max_mm_s;
      e.prev_motion = open_motion_;
      raise_chain(seq);
    }
    open_motion_ = is_quiet(c) && !c.exact_stop ? seq + 1 : 0;
  } else if (!is_transparent(c)) {
    open_motion_ = 0;
  }
  if (c.feed_motion) late_wait_pending_ = false;  // taken when this block starts
  if (waits_at_next_feed_motion(c)) late_wait_pending_ = true;
}

// The motion `next` joined the chain (or its end velocity rose): the motions
// before it may now end faster, as far as `next` can still brake from them.
void LookAheadWindow::raise_chain(std::uint64_t next) {
  for (;;) {
    const Entry& n = at(next);
    if (n.prev_motion == 0 || n.prev_motion - 1 < head_) return;  // none, or it has left
    const std::uint64_t m = n.prev_motion - 1;
    Entry& e = at(m);
    const double v = std::min(e.end_cap_mm_s, entry_limit(n.command));
    if (v == e.command.v_end_mm_s) return;  // nothing changes further back
    e.command.v_end_mm_s = v;
    next = m;
  }
}

// The fastest entry into c from which it still ends at its v_end. The
// profile starts c at the distance the block before ran past its end (up to
// one cycle of travel) and may pass into c up to one braking step faster
// than planned; the margins keep its braking within a_dec nonetheless.
double LookAheadWindow::entry_limit(const Command& c) const {
  const double length = c.segment.length(), a = c.limits.a_dec_mm_s2;
  const double v = motion::entry_velocity_limit(length, c.v_end_mm_s, a, cycle_s_);
  const double shorter = std::max(length - v * cycle_s_, 0.0);
  return std::max(motion::entry_velocity_limit(shorter, c.v_end_mm_s, a, cycle_s_) - a * cycle_s_, 0.0);
}

bool LookAheadWindow::release(kernel::CommandQueue& q, bool flush) {
  const std::size_t keep = flush ? 0 : depth_;
  while (size() > keep) {
    if (q.free_slots() == 0) return false;
    (void)q.push(at(head_).command);  // fits: checked above
    ++head_;
  }
  return true;
}

}  // namespace nck::prep
