#pragma once
// One planned step of a channel as preparation keeps it while it may still
// change: the look-ahead window decides its end velocity and may blend its
// corner. It holds what the window reads (segment, limits, speeds, blend
// state), the kernel command's head and, for a step without motion, its
// action; every technology's data rides along as attachments, in the order
// the units attached them. Leaving the window it is packed into the
// kernel's command and its attachments (command_packer.hpp).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <variant>
#include <vector>

#include "nck/kernel/attachment.hpp"
#include "nck/kernel/command.hpp"
#include "nck/kernel/feed_link.hpp"
#include "nck/motion/cax_transform.hpp"
#include "nck/motion/limits.hpp"
#include "nck/motion/segment.hpp"
#include "nck/prep/weight_scale.hpp"

namespace nck::prep {

using kernel::CssLink;
using kernel::EndReason;
using kernel::FeedLink;
using kernel::Output;
using kernel::SpindleAction;

enum class CommandKind : std::uint8_t {
  motion,    // follow `segment` at `v_cmd_mm_s`
  dwell,     // `step` is a kernel::Dwell
  stop,      // M0 / M1: `step` is a kernel::Hold
  end,       // M2 / M30: `step` is a kernel::End
  error,     // `step` is a kernel::Error: raise it and abort the channel
  nop,       // a block without motion (only its block event and attachments)
};

struct PlannedCommand {
  static constexpr std::size_t kMaxOutputs = kernel::kMaxOutputs;
  static constexpr std::size_t kMaxSpindleActions = kernel::kMaxSpindleActions;
  static constexpr std::size_t kMaxWarnings = 4;

  CommandKind kind = CommandKind::nop;
  // The block it came from, its synchronisation marks, restart and MDI role,
  // and its map's plan-store index: the kernel command's head as it is.
  kernel::CommandHead head{};
  // dwell / stop / end / error: what the kernel does (a motion's action is
  // packed from the fields below)
  std::variant<kernel::Nop, kernel::Dwell, kernel::Hold, kernel::End, kernel::Error> step{};
  // motion: the segment is in machine coordinates, or in program
  // coordinates mapped by a kernel::ProgramMap attachment when a rotation acts
  motion::Segment segment{};
  motion::PathLimits limits{};
  WeightScale weights{};  // the weightings behind `limits` (blend fillets weigh alike)
  double v_cmd_mm_s = 0;
  // Continuous path. The planner gives the highest velocity at which the
  // path may pass from the motion before into this one (corner and feed
  // limits) and whether this block must end at standstill (G60, G360,
  // exact_stop_after_g00); the look-ahead window sets the velocity at its
  // end (0 = exact stop) so that every later block can still be reached.
  double v_entry_max_mm_s = 0;
  // The same for a motion before it that brakes across the transition
  // (braking_staircase.hpp): its braking and the kink share the crossing
  // cycle, so the kink has only what a_max leaves above the braking (STEP;
  // the same value under a jerk-limited slope).
  double v_entry_through_max_mm_s = 0;
  bool exact_stop = false;
  double v_end_mm_s = 0;
  // The next motion chains after it and the corner and feed rules let the
  // path pass between them at the full speed of the slower of the two
  // (kernel::Motion::passes_at_cruise). The look-ahead window sets it when
  // the command leaves (HSC's chains).
  bool passes_at_cruise = false;
  // Passing in (after a fillet or a kink), its first step is limited to
  // start_a_mm_s2 too (kernel::Motion::pass_in_limited; STEP only).
  bool pass_in_limited = false;
  // A fillet follows: it reaches the speed to pass at in the crossing
  // cycle (kernel::Motion::into_fillet; STEP only).
  bool into_fillet = false;
  // It stops at its end only for the sharp corner into the next motion
  // (kernel::Motion::corner_stop; the look-ahead window sets it).
  bool corner_stop = false;
  // Starting from an exact stop right after moving, the first step's
  // acceleration (0: one cycle at standstill). The last step into the stop
  // and the first out of it fall into consecutive cycles; the planner takes
  // the largest at which no axis changes its velocity by more than
  // a_max * dt between them. Infinite: the block's own a_acc.
  double start_a_mm_s2 = std::numeric_limits<double>::infinity();
  // The look-ahead window's braking across its end
  // (kernel::Motion::brake_beyond_mm; STEP only), set when it leaves.
  double brake_beyond_mm = 0;
  // Corner blending (G61/G261): the corner at the end of this feed motion
  // may be replaced by a fillet within this distance of the corner point
  // (#CONTOUR MODE PATH_DEV); 0 = none. The look-ahead window builds it.
  double blend_dev_mm = 0;
  // Spindle couplings (feed_link.hpp), which the corner rules and the
  // window read: a per-cycle limit of the path speed, the spindle following
  // the path (tapping), and G96 (modal, every block; a fillet keeps it).
  FeedLink feed_link{};
  CssLink css{};
  // #FACE / #CYL: the segment is Cartesian; `trafo` maps every set point to the machine.
  motion::CaxTrafo trafo{};
  bool measure = false;  // G100: the motion stops where the probe switches
  // Bit j: the handwheel offset of axis j is in axis j's set point when the
  // block ends (#SUPPRESS OFFSETS and #MCS ON leave it out). A motion block
  // takes it in or out along its path; a block without motion at once.
  std::uint32_t manual_offset_axes = ~0u;
  // What the technologies attach to the block (kernel::Attachment): outputs,
  // spindle actions, warnings, offset events, switches of C axis, links,
  // distance control, manual mode, TRC, the program map.
  std::vector<kernel::Attachment> attachments;

  template <class T>
  void attach(const T& a) { attachments.emplace_back(a); }
  // Attaches a unless the command has `max` of its kind already (false then).
  template <class T>
  bool attach_within(const T& a, std::size_t max) {
    if (count<T>() >= max) return false;
    attach(a);
    return true;
  }
  template <class T>
  void detach() {
    std::erase_if(attachments, [](const kernel::Attachment& a) { return std::holds_alternative<T>(a); });
  }
  // The first attachment of type T, or nullptr.
  template <class T>
  const T* find() const noexcept {
    for (const kernel::Attachment& a : attachments)
      if (const T* t = std::get_if<T>(&a)) return t;
    return nullptr;
  }
  template <class T>
  bool has() const noexcept { return find<T>() != nullptr; }
  template <class T>
  std::size_t count() const noexcept {
    return static_cast<std::size_t>(std::count_if(attachments.begin(), attachments.end(),
                                                  [](const kernel::Attachment& a) { return std::holds_alternative<T>(a); }));
  }
  // Calls f(const T&) for each attachment of type T, in order.
  template <class T, class F>
  void each(F&& f) const {
    for (const kernel::Attachment& a : attachments)
      if (const T* t = std::get_if<T>(&a)) f(*t);
  }
};

// The window keeps up to 128 of them and copies them as it plans
// (docs/architecture.md gives this size; issue 42's bar: at most 1,200 B).
static_assert(sizeof(PlannedCommand) == 1008);

}  // namespace nck::prep
