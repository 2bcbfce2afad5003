#pragma once
// What a channel's technology units receive each cycle: the time, the
// channel's input and event sink, the machine's spindles and PLC outputs,
// and the facts of the channel and of the block it stands at that units may
// read. Units change only their own state (and the spindles they drive);
// what ends the program they return as a Fault, which the channel raises.
#include <array>
#include <cstdint>
#include <span>

#include "nck/kernel/command.hpp"
#include "nck/kernel/queues.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/plc/hli.hpp"
#include "../plc_outputs.hpp"
#include "../spindle_unit.hpp"
#include "../drive_units.hpp"

namespace nck::kernel {

// What a channel reaches besides itself during a cycle.
struct ChannelContext {
  SpindleUnit* spindles = nullptr;  // the machine's spindles, by kernel index
  std::size_t spindle_count = 0;
  PlcOutputs* plc = nullptr;
  const std::array<plc::SpindleControl, kMaxMachineSpindles>* spindle_controls = nullptr;
  DriveReport drives{};  // the CiA 402 drives this cycle (all ready without any)
  bool estop = false;        // the E-stop input is on (TickInput::machine)
  bool machine_off = false;  // the machine-on input is off
  bool drives_enabled = true;  // the NC let the drives be powered in the last cycle
  // The axes' amplifier faults and limit switches (TickInput::axes).
  const std::array<AxisSwitches, drives::kMaxDrives>* axes = nullptr;
  // What the drives reported at the start of this cycle (TickInput::drives).
  const std::array<drives::DriveFeedback, drives::kMaxDrives>* drive_feedback = nullptr;

  // Spindle s (kernel index), or nullptr for none / out of range. rt
  SpindleUnit* spindle(std::int8_t s) const noexcept {
    if (s < 0 || static_cast<std::size_t>(s) >= spindle_count) return nullptr;
    return &spindles[s];
  }
};

// Where command c came from. rt
inline BlockRef block_ref(const Command& c) noexcept { return {c.file_id, c.line, c.n}; }

// Something a unit met that ends the program with an error. The channel
// raises `id` (program state, error event, end) — unless the unit emitted
// the error event itself (`reported`): then the channel only ends the program.
struct Fault {
  ErrorId id{};
  bool reported = false;
  constexpr bool any() const noexcept { return id != ErrorId{}; }
};

// One channel cycle as its units see it.
struct Cycle {
  double t_s = 0;
  double dt_s = 0;
  const ChannelInput& in;
  TickOutput& sink;
  ChannelContext& machine;
  FeedbackQueue& feedback;
  const Command& block;                    // the block the channel stands at
  std::uint8_t channel = 1;                // 1-based
  std::size_t n_axes = 0;
  std::span<const std::int8_t> spindles;  // kernel index per channel spindle
  bool stopped = false;                    // NC stop in force: the path is held as by feedhold
  bool resetting = false;                  // a reset brakes the path as a feedhold does, then ends the program

  // Emits an event at the block the channel stands at. rt
  void emit(const EventPayload& p) const noexcept { sink.emit(Event{{t_s, channel, block_ref(block)}, p}); }
  // Hands a record to preparation. The queue holds more records than can be
  // in flight (queues.hpp); a full one is still reported (preparation would
  // wait for the record for ever), never dropped silently.
  Fault send(const Feedback& f) const noexcept {
    return feedback.push(f) ? Fault{} : Fault{ErrorId::KernelFeedbackOverflow};
  }
};

}  // namespace nck::kernel
