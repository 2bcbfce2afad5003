#pragma once
// The kernel's braking reserve: a motion may end at speed only as far as the
// commands queued after it leave room to stop. Preparation may hand over a
// block that ends at speed before its successor is queued (the look-ahead
// window keeps the successor until it knows what follows); when preparation
// runs in its own thread and falls behind, the kernel must still be able to
// stop within what it has, within every axis's deceleration (LinuxCNC's
// rule: no successor, no speed at the end).
#include "nck/kernel/command.hpp"
#include "nck/kernel/queues.hpp"

namespace nck::kernel {

// The highest speed at which `current` may end: its planned v_end when the
// queued commands after it reach a planned stop, or are long enough to brake
// to standstill within them; otherwise the speed from which the path stops
// within the queued motions (0 without any). rt
// `first`: where in `queued` the commands after `current` begin (HSC asks
// for the last motion of a chain, which is queued itself); `end`: the
// commands looked at end there (a chain's horizon; past the queue's end:
// the whole queue).
double reserve_end_speed(const Motion& current, const CommandQueue& queued, double dt_s,
                         std::size_t first = 0, std::size_t end = kCommandQueueLength) noexcept;

}  // namespace nck::kernel
