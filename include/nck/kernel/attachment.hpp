#pragma once
// What a command carries beside its action, when it carries it: each kind
// belongs to one technology unit of the channel (docs/architecture.md), which
// takes it when the command starts. Preparation puts a command's attachments
// into the command queue right before it (queues.hpp), in the order they are
// to be handled: warnings, offset events and the TRC state are reported in
// that order after the block event; PLC outputs and spindle actions are
// issued in theirs.
#include <array>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <variant>

#include "nck/core/diagnostic.hpp"
#include "nck/distctrl/dist_data.hpp"
#include "nck/frames/offset_event.hpp"
#include "nck/kernel/affine_map.hpp"
#include "nck/kernel/ax_link.hpp"
#include "nck/kernel/event.hpp"
#include "nck/kernel/feed_link.hpp"
#include "nck/kernel/spindle_action.hpp"
#include "nck/motion/axis_vector.hpp"
#include "nck/trc/trc.hpp"

namespace nck::kernel {

// A block's PLC outputs and spindle actions at most.
inline constexpr std::size_t kMaxOutputs = 8;
inline constexpr std::size_t kMaxSpindleActions = 16;

// A channel function output to the PLC with the block (M, H, T); its
// synchronisation bits decide when it is output and waited for.
struct Output {
  plc::TechKind fn = plc::TechKind::none;
  std::int32_t number = 0;
  std::uint32_t sync = 0;
  double ack_timeout_s = 0;  // 0 = none
  std::optional<std::int32_t> value;  // M52=-345: the additional value the PLC gets
};

// The motion starts here, not where the motion before it ended (a changed
// frame, a transformation switched, after G100 or homing).
struct StartPoint {
  motion::AxisVector pos{};
};

// The motion's segment is in program coordinates: this maps them to the
// machine (a rotation acts).
struct ProgramMap {
  AffineMap map{};
};

// A warning raised with the block: the event it is reported as, right
// after the block event.
using Warning = ev::Warning;

// G201 / G202: axes entering / leaving manual (handwheel) mode (bit j =
// axis j); #GET MANUAL OFFSETS: preparation reads the offsets after it.
struct ManualChange {
  std::uint32_t on = 0, off = 0;
  bool get_offsets = false;
};

// #CAX: spindle `spindle` (kernel index) becomes channel axis `axis`, and
// the channel reports its position back; #CAX OFF: a spindle again.
struct CaxChange {
  bool on = true;
  std::int8_t spindle = 0;
  std::int8_t axis = 0;
};

// G74: the command homes these path axes (bit j = axis j); the kernel
// marks them homed when the command ends at their home position.
struct HomeAxes {
  std::uint32_t mask = 0;
};

using distctrl::DistChange;
using frames::OffsetEvent;
using trc::TrcChange;

// The order of the alternatives is the order in which the channel handles
// a command's attachments (CommandPacker sorts them so): what is reported
// as events first (after the block event), then the units' switches, then
// the outputs and spindle actions in the order they were planned.
using Attachment = std::variant<Warning, OffsetEvent, TrcChange, CaxChange, LinkCommand, DistChange, FeedLink,
                                CssLink, ManualChange, Output, SpindleAction, StartPoint, ProgramMap, HomeAxes>;

// Attachments cross the real-time queue, maybe in shared memory.
static_assert(std::is_trivially_copyable_v<Attachment>);

}  // namespace nck::kernel
