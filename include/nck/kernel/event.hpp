#pragma once
// Events the kernel emits in the cyclic path: a head (when, which channel,
// which block) and one typed payload per kind, each defined with its JSON
// writer in its technology's header. Plain data, no strings, so producing
// one never allocates; the run service writes them as JSON lines
// (docs/outputs.md), looking texts up by index.
#include <cstdint>
#include <type_traits>
#include <variant>

#include "nck/core/event_head.hpp"
#include "nck/distctrl/dist_data.hpp"
#include "nck/drives/drive_event.hpp"
#include "nck/frames/offset_event.hpp"
#include "nck/kernel/ax_link.hpp"
#include "nck/kernel/channel_events.hpp"
#include "nck/kernel/machine_event.hpp"
#include "nck/kernel/sync_events.hpp"
#include "nck/spindle/spindle_events.hpp"
#include "nck/trc/trc.hpp"

namespace nck::kernel {

// The kinds in the order of EventPayload's alternatives.
enum class EventKind : std::uint8_t {
  block,      // a block starts executing
  plc_out,    // a function is output to the PLC
  plc_ack,    // the PLC acknowledged it
  wait,       // the channel starts waiting
  wait_end,   // ... and stops waiting
  spindle,    // a spindle changes mode
  speed_reached,
  gear,
  link,
  offset,
  stop,       // M0 / M1 programmed stop
  warning,
  error,
  end,        // program end of a channel
  dist_ctrl,  // 3D distance control changed state
  trc,        // tool radius compensation selected, deselected or its D changed
  state,      // the channel's program state changed
  machine,    // E-stop / machine on changed what the machine does (channel 0)
  drive,      // a CiA 402 drive reports another mode of operation (channel 0)
};

using EventPayload =
    std::variant<ev::Block, ev::PlcOut, ev::PlcAck, ev::Wait, ev::WaitEnd, spindle::ModeEvent,
                 spindle::SpeedReachedEvent, spindle::GearEvent, LinkEvent, frames::OffsetEvent, ev::Stop,
                 ev::Warning, ev::Error, ev::End, distctrl::StateEvent, trc::TrcChange, ev::State, ev::Machine, drives::DriveEvent>;

// "block", "plc_out", ... as the events file writes them.
constexpr const char* event_name(EventKind k) noexcept {
  constexpr const char* kNames[] = {"block", "plc_out", "plc_ack", "wait",    "wait_end", "spindle",
                                    "speed_reached", "gear", "link", "offset", "stop", "warning",
                                    "error", "end", "dist_ctrl", "trc", "state", "machine", "drive"};
  static_assert(std::size(kNames) == std::variant_size_v<EventPayload>);
  return kNames[static_cast<std::size_t>(k)];
}

struct Event : EventHead {
  EventPayload payload{};

  EventKind kind() const noexcept { return static_cast<EventKind>(payload.index()); }
  template <class T>
  const T* get() const noexcept { return std::get_if<T>(&payload); }
};

// The index of payload type T, which is its kind.
template <class T, std::size_t I = 0>
constexpr EventKind kind_of() noexcept {
  if constexpr (std::is_same_v<T, std::variant_alternative_t<I, EventPayload>>) return static_cast<EventKind>(I);
  else return kind_of<T, I + 1>();
}
static_assert(kind_of<ev::State>() == EventKind::state && kind_of<ev::Error>() == EventKind::error &&
              kind_of<distctrl::StateEvent>() == EventKind::dist_ctrl);

// Events cross the real-time queues and may sit in shared memory.
static_assert(std::is_trivially_copyable_v<Event>);
static_assert(sizeof(Event) == 80, "docs/architecture.md gives the event's size");

}  // namespace nck::kernel
