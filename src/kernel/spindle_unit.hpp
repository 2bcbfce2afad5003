#pragma once
// One spindle of the machine as the kernel runs it: the interpolator, what
// the channels' events need to notice changes, and the gear-change job
// (approach the change position, let the PLC shift, take the new data).
// A spindle known to several channels is one unit.
#include <cstdint>
#include <optional>

#include "nck/core/ring_buffer.hpp"
#include "nck/kernel/spindle_action.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/plc/ext_command.hpp"
#include "nck/plc/hli.hpp"
#include "plc_outputs.hpp"
#include "nck/spindle/spindle_axis.hpp"

namespace nck::kernel {

enum class GearJob : std::uint8_t { none, approaching, shifting, done };

struct SpindleUnit {
  spindle::SpindleAxis axis;
  bool plc_spindle = false;      // commanded over the HLI, acknowledged by the PLC
  std::uint8_t channel = 1;      // the channel that commanded it last (1-based)
  std::int8_t channel_index = 0; // its index in that channel's spindle list
  std::int16_t axis_list = -1;   // its machine axis list index (TickInput::axes: amplifier fault), -1 none
  std::int16_t cia402_axis = -1; // the same when its drive is CiA 402, else -1
  std::int16_t conventional_axis = -1;  // the same when its drive is conventional (antr_typ 1), else -1
  // The machine measures it (TickInput: spindle_measured, its CiA 402
  // drive's actual values), not a simulated drive attached to the kernel.
  bool machine_measured = false;
  // Synchronous operation: the channel whose enabled coupling groups hold
  // this spindle as master or slave (0 = none), and in how many groups.
  std::uint8_t link_channel = 0;
  std::uint8_t link_groups = 0;

  // gear change in progress
  GearJob gear_job = GearJob::none;
  std::uint32_t gear_stage = 0;
  plc::OutputHandle gear_handle = plc::kNoHandle;
  bool gear_acked = false;
  bool gear_output_delayed = false;  // reported once: the PLC's outputs were full

  // Endless rotation as the channels left it, beyond what the interpolator's
  // mode tells: the direction of the last M3/M4 (a spindle may turn at 0 rpm
  // after M3 without a speed), and whether a gear change interrupted a
  // rotation (only M5, G74 and M19 end it, FCT-S1 2.3.1).
  std::int8_t rotation_dir = 1;
  // G96: a channel sets the speed every cycle; its changes are not events.
  bool speed_law = false;
  bool rotation_across_gear_change = false;

  // external commands (HLI): those waiting for this spindle in order of
  // arrival, and the one in progress (sequence number, 0 = none; M function)
  RingBuffer<plc::ExtSpindleCommand, plc::ExtCommandQueue::kCapacity> ext_waiting;
  std::uint32_t ext_seq = 0;
  std::int32_t ext_m = 0;

  // what was last reported, to emit events on change
  spindle::SpindleMode last_mode = spindle::SpindleMode::stop;
  double last_cmd_rpm = 0;
  bool last_speed_reached = false;
  std::uint32_t last_gear = 1;
  // what the last report saw: with the same, it has nothing new to say
  std::uint64_t reported_judgements = ~0ull;
  bool reported_speed_law = false;
};

// Emits spindle / speed_reached events for what changed since
// the last cycle. rt
void report_spindle_changes(SpindleUnit& u, std::int8_t index, double t_s, TickOutput& out) noexcept;

// Advances a gear change: at the change position the function goes to the
// PLC; its acknowledgement (gear_acked) finishes the change. rt
void advance_gear_job(SpindleUnit& u, std::int8_t index, PlcOutputs& plc, double t_s,
                      TickOutput& out) noexcept;

// The signed speed an S word alone commands now, or nullopt when it only
// stores the speed: it changes the speed of a spindle in endless rotation,
// whoever started it. rt
std::optional<double> speed_change_rpm(const SpindleUnit& u, double rpm) noexcept;

// Records what a channel's spindle action does to the endless rotation. rt
void note_rotation(SpindleUnit& u, const SpindleAction& a) noexcept;

// The HLI status object of a spindle. rt
void fill_hli_status(const SpindleUnit& u, plc::SpindleStatus& s) noexcept;

}  // namespace nck::kernel
