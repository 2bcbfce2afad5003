#pragma once
// One planned step of a channel as preparation keeps it while it may still
// change (the look-ahead window decides its end velocity and may blend its
// corner). Leaving the window it is packed into the kernel's compact
// PlannedCommand and its attachments (command_packer.hpp).
#include <array>
#include <cstdint>
#include <optional>

#include "nck/core/diagnostic.hpp"
#include "nck/core/fixed_vector.hpp"
#include "nck/distctrl/controller.hpp"
#include "nck/frames/offset_chain.hpp"
#include "nck/kernel/affine_map.hpp"
#include "nck/kernel/attachment.hpp"
#include "nck/kernel/command.hpp"
#include "nck/kernel/ax_link.hpp"
#include "nck/kernel/event.hpp"
#include "nck/kernel/feed_link.hpp"
#include "nck/kernel/spindle_action.hpp"
#include "nck/motion/cax_transform.hpp"
#include "nck/motion/limits.hpp"
#include "nck/prep/weight_scale.hpp"
#include "nck/motion/segment.hpp"
#include "nck/nc/modal.hpp"

namespace nck::prep {

using kernel::CssLink;
using kernel::EndReason;
using kernel::FeedLink;
using kernel::Output;
using kernel::SpindleAction;

enum class CommandKind : std::uint8_t {
  motion,    // follow `segment` at `v_cmd_mm_s`
  dwell,     // wait `dwell_s`
  stop,      // M0 / M1 (`optional_stop`: M1 stops only while the HLI asks)
  end,       // M2 / M30: program end
  error,     // raise `error_id` and abort the channel
  nop,       // a block without motion (only its block event and outputs)
};

struct PlannedCommand {
  static constexpr std::size_t kMaxOutputs = kernel::kMaxOutputs;
  static constexpr std::size_t kMaxSpindleActions = kernel::kMaxSpindleActions;

  CommandKind kind = CommandKind::nop;
  // the block it came from
  std::uint16_t file_id = 0;
  std::uint32_t line = 0;
  bool has_n = false;
  std::int64_t n = 0;
  bool emit_block_event = true;  // false for follow-up commands of one block
  kernel::Restart restart = kernel::Restart::none;  // block search (block_search.hpp)
  kernel::Mdi mdi = kernel::Mdi::none;              // MDI (channel_prep.hpp)
  // PlanStore::frames index of the block's program -> machine map, handed on
  // in the block event (none: not recorded)
  std::optional<std::uint32_t> frame_index;
  // motion: the segment is in machine coordinates, or in program
  // coordinates mapped by `map` when a rotation acts (mapped == true)
  motion::Segment segment{};
  bool mapped = false;
  kernel::AffineMap map{};
  motion::PathLimits limits{};
  WeightScale weights{};  // the weightings behind `limits` (blend fillets weigh alike)
  double v_cmd_mm_s = 0;
  // Continuous path. The planner gives the highest velocity at which the
  // path may pass from the motion before into this one (corner and feed
  // limits) and whether this block must end at standstill (G60, G360,
  // exact_stop_after_g00); the look-ahead window sets the velocity at its
  // end (0 = exact stop) so that every later block can still be reached.
  double v_entry_max_mm_s = 0;
  bool exact_stop = false;
  double v_end_mm_s = 0;
  // The next motion chains after it and the corner and feed rules let the
  // path pass between them at the full speed of the slower of the two
  // (kernel::Motion::passes_at_cruise). The look-ahead window sets it when
  // the command leaves (HSC's chains).
  bool passes_at_cruise = false;
  // It follows a fillet and start_a_mm_s2 is also its first step when
  // passing in from it (kernel::Motion::after_fillet; STEP only).
  bool after_fillet = false;
  // A fillet follows: it reaches the speed to pass at in the crossing
  // cycle (kernel::Motion::into_fillet; STEP only).
  bool into_fillet = false;
  // Starting from an exact stop right after moving, the first step's
  // acceleration (0: one cycle at standstill). The last step into the stop
  // and the first out of it fall into consecutive cycles; the planner takes
  // the largest at which no axis changes its velocity by more than
  // a_max * dt between them. None: the block's own a_acc.
  std::optional<double> start_a_mm_s2;
  // Corner blending (G61/G261): the corner at the end of this feed motion
  // may be replaced by a fillet within this distance of the corner point
  // (#CONTOUR MODE PATH_DEV); 0 = none. The look-ahead window builds it.
  double blend_dev_mm = 0;
  // spindle couplings (feed_link.hpp): a per-cycle limit of the path speed,
  // the spindle following the path (tapping), and G96 (modal, every block)
  FeedLink feed_link{};
  CssLink css{};
  // dwell: `dwell_s` seconds, or (G4 S..) `dwell_revs` revolutions of
  // spindle `dwell_spindle` (kernel index), counted as it really turns
  double dwell_s = 0;
  double dwell_revs = 0;
  std::int8_t dwell_spindle = -1;
  // stop
  bool optional_stop = false;
  // end / error
  EndReason end_reason = EndReason::m30;
  ErrorId error_id{};
  std::uint32_t message_index = 0;
  // PLC outputs of the block and its spindle functions, in execution order
  FixedVector<Output, kMaxOutputs> outputs;
  FixedVector<SpindleAction, kMaxSpindleActions> spindle_actions;
  bool feed_motion = false;  // G1/G2/G3: MVS_SLM functions synchronise here
  // G201 / G202: axes entering / leaving manual (handwheel) mode, bit j = axis j
  std::uint32_t manual_on = 0, manual_off = 0;
  bool get_manual_offsets = false;  // #GET MANUAL OFFSETS: the decoder reads them after this block
  // Bit j: the handwheel offset of axis j is in axis j's set point when the
  // block ends (#SUPPRESS OFFSETS and #MCS ON leave it out). A motion block
  // takes it in or out along its path; a block without motion at once.
  std::uint32_t manual_offset_axes = ~0u;
  // G100: the motion stops where the probe switches
  bool measure = false;
  bool expl_syn = false;     // #EXPL SYN: MVS_SLP functions synchronise here
  // offset events (PlanStore::offsets, at most one per kind) and warnings
  // raised with the block (beyond kMaxWarnings the last says how many more)
  FixedVector<std::uint32_t, frames::kOffsetKinds> offset_events;
  static constexpr std::size_t kMaxWarnings = 4;
  FixedVector<kernel::Warning, kMaxWarnings> warnings;
  // C-axis machining (#CAX, #FACE, #CYL). cax on: the spindle `cax_spindle`
  // (kernel index) becomes channel axis `cax_axis` when the command starts,
  // and the channel reports its position back (FeedbackKind::c_axis); off:
  // it is a spindle again. A motion under #FACE / #CYL has its segment in
  // Cartesian coordinates; `trafo` maps every set point to the machine.
  enum class CaxOp : std::uint8_t { none, on, off };
  CaxOp cax = CaxOp::none;
  std::int8_t cax_spindle = -1;
  std::int8_t cax_axis = -1;
  motion::CaxTrafo trafo{};
  // #ENABLE / #DISABLE AX LINK (ax_link.hpp), done when the block starts
  kernel::LinkCommand link{};
  // #DIST CTRL: the switch and its overrides (dist.any()), the tool axis that
  // carries the offset (plane's third axis) and, with check_sw_limit_switch,
  // that axis's software limits.
  distctrl::Switch dist{};
  std::int8_t dist_axis = -1;
  // SENSOR_SOURCE (none: keep), and the channel variable it names
  std::optional<kernel::DistChange::Source> dist_source;
  std::array<char, 32> dist_var{};
  bool dist_check_sw = false;
  double dist_sw_neg_mm = 0, dist_sw_pos_mm = 0;
  // Tool radius compensation changed with this block (a `trc` event when it
  // starts): the mode, the D in force and its tool radius.
  std::optional<kernel::TrcChange> trc;
};

}  // namespace nck::prep
