#pragma once
// One planned step of a channel as its cyclic executor runs it: a small
// header naming the block it comes from, and what to do — a motion, a dwell,
// a programmed hold, the program end, an error, or nothing (a block without
// motion). What only some blocks carry (PLC outputs, spindle actions,
// couplings, switches of C axis, links, distance control ...) travels beside
// the command as attachments (attachment.hpp) in the same queue
// (queues.hpp); the header says how many.
//
// Plain fixed-size data, at most 512 bytes (a static_assert holds it): the
// queue between preparation and tick() holds these.
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <variant>

#include "nck/core/diagnostic.hpp"
#include "nck/kernel/event.hpp"
#include "nck/motion/cax_transform.hpp"
#include "nck/motion/limits.hpp"
#include "nck/motion/segment.hpp"

namespace nck::kernel {

// Follow a path segment. Its start is where the motion before ended (or a
// StartPoint attachment); a ProgramMap attachment says that it is in
// program coordinates and maps them to the machine (a rotation acts).
struct Motion {
  motion::SegmentTail path{};
  motion::PathLimits limits{};
  double v_cmd_mm_s = 0;
  // The velocity at its end that the look-ahead planned (0 = exact stop).
  double v_end_mm_s = 0;
  // Starting from an exact stop right after moving, the first step's
  // acceleration (the planner's limit for a sharp turn or a reversal);
  // infinite: the block's own acceleration.
  double start_a_mm_s2 = std::numeric_limits<double>::infinity();
  // STEP: > 0 when the path brakes across this block's end rather than
  // passing it at v_end_mm_s: it follows the braking staircase (a_dec of
  // `limits`) to standstill at this distance past its end, which the
  // motions after it continue (PathProfile::brake_through; the look-ahead
  // window's "through" motions). v_end_mm_s is then the least speed it
  // passes on with.
  double brake_beyond_mm = 0;
  // #FACE / #CYL: the segment is Cartesian; every set point is mapped.
  motion::CaxTrafo trafo{};
  bool measure : 1 = false;  // G100: the motion stops where the probe switches
  // The transition at its end may be passed at the full speed of both
  // motions: the corner and feed rules do not lower it below the slower
  // one's cruise (the planned v_end_mm_s may still be lower, for the
  // braking of the blocks after it). HSC runs its chains across such
  // transitions. (Flags of one bit here: Command stays at 504 bytes;
  // at 512, the queue's entries fell on the same cache sets.)
  bool passes_at_cruise : 1 = false;
  // Passing in from the motion before, its first step changes the speed by
  // at most start_a_mm_s2 (STEP): after a fillet, what the rest of the
  // fillet's turn in that step leaves of a_max (the fillet's own, lower,
  // would apply otherwise); after a kink passed at speed, what the kink's
  // share in that step leaves.
  bool pass_in_limited : 1 = false;
  // A fillet follows and the path passes into it: the speed to pass at is
  // reached in the crossing cycle (PathProfile::pass_into_fillet; the
  // window keeps this motion's accelerations within what the fillet's
  // first part leaves of a_max).
  bool into_fillet : 1 = false;
  // The path stops at its end only because the corner into the next
  // motion lets no speed pass (time by cause: "corner", not acceleration).
  bool corner_stop : 1 = false;
  // Bit j: axis j's handwheel offset is in its set point when the motion
  // ends (#SUPPRESS OFFSETS and #MCS ON leave it out); taken in or out
  // along the path.
  std::uint32_t handwheel_axes = ~0u;
};

// G4: a time, or as many revolutions as a spindle really turns (G4 S..).
struct Dwell {
  struct Revolutions {
    double revs = 0;
    std::int8_t spindle = 0;  // kernel index
  };
  double time_s = 0;
  std::optional<Revolutions> revolutions;
};

// M0 / M1: a programmed hold (M1 only while the optional-stop switch is on).
struct Hold {
  bool optional_stop = false;
};

// M2 / M30.
struct End {
  EndReason reason = EndReason::m30;
};

// Raise `id` and abort the channel.
struct Error {
  ErrorId id{};
  std::optional<std::uint32_t> message;  // Kernel::message() index; none: the ID's table text
};

// A block without motion: its block event, attachments and waits only.
struct Nop {};

using Action = std::variant<Nop, Motion, Dwell, Hold, End, Error>;

// Block search (prep/block_search.hpp): the commands that frame a restart.
enum class Restart : std::uint8_t {
  none,
  search_begins,    // a Nop: the channel searches (decodes without motion) up to the mark
  returns,          // the return to the contour; the channel holds after it for cycle start
  returns_no_hold,  // the same without the hold (HLI no_hold_at_restart)
};

// MDI (prep/channel_prep.hpp): a command of the operator's text, or the
// one after its last that returns the channel to idle.
enum class Mdi : std::uint8_t { none, block, end };

// What a command says besides its action: the block it came from, its
// synchronisation marks, its role in a block search or MDI, its map.
struct CommandHead {
  std::uint16_t file_id = 0;
  std::uint32_t line = 0;
  std::optional<std::int64_t> n;
  bool emit_block_event = true;  // false for follow-up commands of one block
  bool feed_motion = false;      // G1/G2/G3: MVS_SLM functions synchronise here
  bool expl_syn = false;         // #EXPL SYN: MVS_SLP functions synchronise here
  Restart restart = Restart::none;
  Mdi mdi = Mdi::none;
  // How many early program ends (reset, error: the kernel's `stopped`
  // feedback) preparation had taken when it planned this. The kernel drops
  // a command planned before its latest such end: it would start where the
  // path no longer stands.
  std::uint8_t stops_taken = 0;
  // PlanStore::frames index of the block's program -> machine map, handed on
  // in the block event (none: not recorded)
  std::optional<std::uint32_t> frame_index;
};

struct Command : CommandHead {
  std::uint16_t attachments = 0;  // how many attachments precede it in the queue
  Action action{};

  template <class T>
  bool is() const noexcept { return std::holds_alternative<T>(action); }
  template <class T>
  const T* as() const noexcept { return std::get_if<T>(&action); }
};

static_assert(sizeof(Command) <= 512, "a queued command stays small (docs/performance.md)");
static_assert(sizeof(Command) == 504, "docs/architecture.md gives the command's size");
static_assert(std::is_trivially_copyable_v<Command>, "commands cross the real-time queue, maybe in shared memory");

}  // namespace nck::kernel
