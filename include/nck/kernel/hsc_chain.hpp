#pragma once
// HSC (#SLOPE [TYPE=HSC], P-CHAN-00071 = 3, "trapezoidal across blocks"):
// the motion that starts and the queued motions after it that the path
// runs through at its speed form one chain, which the profile plans as one
// jerk-limited move (motion::PathChain): the acceleration goes on across
// the transitions inside it instead of returning to 0 at every block end.
// Under TRAPEZ the spans of one smoothed polyline chain the same
// way (docs/decisions.md, "Smoothing fine chords"): together they are one
// curve, as a spline through the programmed points is on an ISG control.
#include <algorithm>
#include <cstddef>

#include "nck/kernel/command.hpp"
#include "nck/kernel/queues.hpp"
#include "nck/motion/path_profile.hpp"

namespace nck::kernel {

// How far into the queue a chain looks (commands). Preparation keeps at
// least kMaxLookAheadDepth commands queued before each cycle whether it
// runs in its own thread or not, but how many more it has queued depends
// on when it ran; a chain that looked at all of them would differ between
// the two (`--prep-thread` equals the plain run). The margin covers the
// commands a cycle takes before a chain is planned (blocks without motion
// take no cycle of their own).
inline constexpr std::size_t kChainHorizon = kMaxLookAheadDepth - 16;

struct HscChain {
  motion::PathChain chain{};  // length 0: the motion alone (no successor joins)
  // The chain reaches the end of the queue: more queued commands may make
  // it longer (and its end faster), so it is looked at again when the
  // queue grows (also while no motion has joined yet).
  bool open = false;
  std::size_t queued_seen = 0;  // the commands it looked at: queued.size(), at most kChainHorizon
};

// The chain that starts with `current` (length_mm of its segment, cruise
// min(v_cmd, v_max)). A motion joins while every transition on the way is
// passable at the chain's speed: the corner and feed rules let it pass at
// the speed of its motions (Motion::passes_at_cruise) and the joining
// motion's cruise is at least the current motion's; HSC, no
// transformation, no probing, only blocks without motion between. The chain's limits are its motions'
// smallest accelerations and speed limits and longest ramp times. It ends
// at its last motion's planned end speed, lowered by the braking reserve
// of what is queued after it; at the end of the queue, at 0. rt
// Whether m is a span of a smoothed polyline under TRAPEZ,
// and whether a chain may start with m (HSC, or such a span). rt
bool chains_as_spline(const Motion& m) noexcept;
bool chains(const Motion& m) noexcept;

HscChain hsc_chain(const Motion& current, double length_mm, const CommandQueue& queued, double dt_s) noexcept;
// The commands of `queued` a chain looks at. rt
inline std::size_t chain_view(const CommandQueue& queued) noexcept { return std::min(queued.size(), kChainHorizon); }

}  // namespace nck::kernel
