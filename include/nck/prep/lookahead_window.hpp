#pragma once
// The look-ahead window of a channel's preparation: planned commands wait
// here until `depth` later commands are known (P-CHAN-00653), then leave
// for the command queue with the velocity at their end decided.
//
// Velocity look-ahead: consecutive motions form a chain when nothing between
// them needs the path at standstill (an output or spindle function, a wait,
// a dwell, a stop, G60/G360 ...; see docs/decisions.md, "Continuous path and
// corner blending"). Within a chain each transition may be passed at the
// planner's corner/feed limit, but never so fast that the blocks after it could
// not brake in time: the end of the window is taken as a stop (nothing later is
// known), and a backward pass lowers each transition to what the rest of the
// chain can absorb. Under STEP a motion may brake across its end along the
// staircase of the motions after it instead of holding its end speed
// (braking_staircase.hpp). Appending a block only ever raises earlier
// transitions, so a command that has left is never too fast; the pass stops
// at the first motion whose staircase does not change, which keeps the cost
// per block small.
//
// Corner blending (G61/G261, docs/decisions.md, "Continuous path and corner
// blending"): when a motion chains after one whose end may be blended
// (PlannedCommand::blend_dev_mm), a circular fillet or (STEP, where its corner
// costs less time) a parabola (motion/corner_blend.hpp), as small as lets the
// path pass at the feed, is put between them as a motion command of its own,
// both neighbours shortened to its tangent points (each block shared between
// its two corners; blocks without motion between them are moved after it);
// where none fits, the corner stays sharp with its velocity limit.
//
// This is also where tool radius compensation will act on a span of
// upcoming blocks. Setup side: never called from tick().
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "nck/core/fixed_vector.hpp"
#include "nck/kernel/queues.hpp"
#include "nck/motion/corner_blend.hpp"
#include "nck/motion/limits.hpp"
#include "nck/prep/blend_limits.hpp"
#include "nck/prep/braking_staircase.hpp"
#include "nck/prep/command_packer.hpp"
#include "nck/prep/planned_command.hpp"

namespace nck::prep {

// The commands one block planned into.
using PlannedBlock = FixedVector<PlannedCommand, kernel::kMaxCommandsPerBlock>;

// What blending needs of the channel's axes (from the planner, setup).
struct BlendAxes {
  std::size_t n_axes = 0;
  std::array<motion::AxisDynamics, kMaxAxes> feed_dyn{};  // G1/G2/G3 dynamics per axis
  std::array<double, kMaxAxes> corner_dv_mm_s{};           // kink budget per axis and cycle (STEP)
  std::array<double, kMaxAxes> jerk_corner_dv_mm_s{};      // the same under a jerk-limited slope
  std::array<double, kMaxAxes> a_max_mm_s2{};              // hard cap of every acceleration per axis
};

// Totals over the run, for reports and benchmarks.
struct BlendStats {
  std::uint64_t blends = 0;      // blends placed (fillets and parabolas)
  std::uint64_t parabolas = 0;   // of them parabolas (STEP)
  std::uint64_t smoothed = 0;    // vertices smoothed into cubic spans (jerk-limited slopes)
  double shortfall_mm = 0;       // programmed length minus blended length, summed
  double max_deviation_mm = 0;   // largest corner-to-blend distance
};

class LookAheadWindow {
 public:
  // setup: depth = commands that stay behind a command before it leaves;
  // cycle_s = the kernel's cycle (its braking is discrete).
  explicit LookAheadWindow(std::size_t depth = 0, double cycle_s = 0.001);

  std::size_t depth() const { return depth_; }
  std::size_t size() const { return static_cast<std::size_t>(tail_ - head_); }
  bool empty() const { return head_ == tail_; }
  // Room for one more block without releasing first.
  // (each motion may bring a fillet along: two entries per command)
  bool has_room() const { return size() + 2 * kernel::kMaxCommandsPerBlock <= ring_.size(); }
  // setup: the axes' dynamics, needed before a blend can be placed.
  void set_blend_axes(const BlendAxes& axes) { axes_ = axes; }
  const BlendStats& blend_stats() const { return stats_; }
  // Appends a block's commands (false when there is no room: release first).
  bool push(const PlannedBlock& b);

  // Hands the commands that have `depth` successors (all of them when
  // flushing) to q while it has room. True when nothing that should leave
  // is left behind.
  bool release(kernel::CommandQueue& q, bool flush);
  // The program was ended by the kernel: nothing in the window leaves.
  void drop_all() { head_ = tail_; }
  // Commands handed to the queue so far.
  std::uint64_t released() const { return head_; }

 private:
  struct Entry {
    PlannedCommand command;
    std::uint64_t prev_motion = 0;  // sequence number + 1 of the motion chained before, 0 = none
    double end_cap_mm_s = 0;        // corner/feed limit at its end while chained, else 0
    double through_cap_mm_s = 0;    // the same for braking across its end (EndCaps)
    EndCaps caps() const { return {end_cap_mm_s, through_cap_mm_s}; }
    Staircase stairs{};             // how it brakes (motions)
    // The limits preparation gave the motion, before smoothing narrowed
    // them for a span's curvature (which changes as its vertices are smoothed).
    motion::PathLimits chord_limits{};
  };
  Entry& at(std::uint64_t seq) { return ring_[seq % ring_.size()]; }
  const Entry& at(std::uint64_t seq) const { return ring_[seq % ring_.size()]; }
  void append(const PlannedCommand& c);
  void store(const PlannedCommand& c, bool linkable);
  void raise_chain(std::uint64_t seq);
  void settle(std::uint64_t seq, const Staircase* next);
  // The first command whose staircase may still be lowered: none that has
  // left, nor one that a command which has left brakes across into.
  std::uint64_t first_open() const { return std::max(head_, fixed_end_); }
  void blend_across(PlannedCommand& c);
  bool passes_at_cruise(std::uint64_t seq) const;
  bool blend(std::uint64_t prev, PlannedCommand& next);
  // The vertex between prev and next smoothed (motion/chord_smoothing.hpp):
  // both become cubic spans; false (nothing changed) where it cannot be
  // smoothed or would pass slower than the kink.
  bool smooth(std::uint64_t prev, PlannedCommand& next, const BlendAxes& ax, const BlendDynamics& dyn);
  // smooth() narrowed the next motion's limits: its chord's, for store().
  std::optional<motion::PathLimits> next_chord_limits_;
  std::optional<motion::CornerBlend> corner_blend(const Entry& p, const PlannedCommand& next, const BlendDynamics& dyn,
                                                  motion::PathLimits& limits) const;
  double corner_cost(const motion::CornerBlend& cb, const motion::PathLimits& l, const PlannedCommand& before,
                     const PlannedCommand& after) const;
  double ramps_cost(double v_mm_s, const PlannedCommand& before, const PlannedCommand& after) const;
  static motion::PathLimits jerk_fillet_limits(const motion::Segment& fillet, const BlendDynamics& d,
                                               const motion::PathLimits& before, double feed_mm_s);
  bool lowering_is_safe(std::uint64_t seq, Staircase changed) const;
  double cruise(const PlannedCommand& c) const;
  double tangent_cap(const PlannedCommand& from, const PlannedCommand& to, const BlendAxes& ax) const;
  static WeightScale both(const WeightScale& a, const WeightScale& b);
  const BlendAxes& weighted_axes(const WeightScale& w);

  std::vector<Entry> ring_;
  std::uint64_t head_ = 0, tail_ = 0;  // sequence numbers: [head_, tail_) are in the window
  std::uint64_t fixed_end_ = 0;  // before it, staircases are only raised (first_open)
  std::size_t depth_;
  double cycle_s_;
  std::uint64_t open_motion_ = 0;  // sequence number + 1 of a motion whose end may still blend
  bool late_wait_pending_ = false;  // an MVS_SLM function waits at the next feed motion
  BlendAxes axes_{};
  BlendAxes weighted_{};  // axes_ under a corner's weightings (scratch)
  BlendStats stats_{};
  CommandPacker packer_;  // packs what leaves for the queue
};

}  // namespace nck::prep
