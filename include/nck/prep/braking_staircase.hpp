#pragma once
// How a motion in the look-ahead window brakes (docs/decisions.md, "Braking
// across short blocks"). A motion that holds its planned end speed reaches it
// a little before its end and passes on at exactly that speed: the margins
// that make this safe cost about four cycles of travel at every block end,
// so over blocks shorter than that the path could never reach its feed (the
// surface-finishing program's 0.25 mm steps stayed near 30 mm/s at F3000).
// Under STEP a motion may instead brake across its end: it follows the
// braking staircase of the motions after it, down to the end speed of a
// later motion that holds its own, and the margins are paid once, there.
// Setup side (preparation).
#include <cstdint>

#include "nck/prep/planned_command.hpp"

namespace nck::prep {

struct Staircase {
  double entry_mm_s = 0;  // the fastest entry from a motion that holds its end speed
  double stand_mm = 0;    // from the motion's start to where its staircase comes to rest
  double a_mm_s2 = 0;     // the staircase's deceleration
  // Braking across: where the staircase of the motions after it comes to
  // rest, past its end (its own stand_mm also counts the ceiling at its end,
  // which the kernel holds by itself).
  double across_mm = 0;
  std::uint64_t reference = 0;  // the motion whose held end speed the staircase leads to
  bool through = false;   // it brakes across its end (kernel::Motion::brake_beyond_mm)
  bool step = false;      // under STEP (a discrete staircase a motion before it may follow)
  bool operator==(const Staircase&) const = default;
  // Nowhere lower than `s` (the same or a later standstill point, no gentler).
  bool covers(const Staircase& s) const { return stand_mm >= s.stand_mm && a_mm_s2 >= s.a_mm_s2; }
};

// The fastest entry into c from which it still ends at its v_end, holding
// it. The profile starts c at the distance the block before ran past its
// end (up to one cycle of travel) and may pass into c up to one braking
// step faster than planned; the margins keep its braking within a_dec.
double holding_entry_limit(const PlannedCommand& c, double dt_s);

// How fast the corner at a motion's end may be passed: holding the speed
// (the planned v_end's cap) and braking across it (the kink shares its
// crossing cycle with a braking step: PlannedCommand::v_entry_through_max_mm_s).
struct EndCaps {
  double holding_mm_s = 0;
  double through_mm_s = 0;
  static EndCaps both(double v_mm_s) { return {v_mm_s, v_mm_s}; }
};

// How c (sequence number seq, its planned v_end set) brakes: holding its
// end speed, or braking across its end along next's staircase where both
// run under STEP, c passes on at speed, the staircase never crosses faster
// than the corner allows braking across (caps.through_mm_s) and lets the
// path enter c faster. next: the motion chained after c (nullptr: none).
Staircase settle(const PlannedCommand& c, std::uint64_t seq, EndCaps caps, const Staircase* next, double dt_s);

}  // namespace nck::prep
