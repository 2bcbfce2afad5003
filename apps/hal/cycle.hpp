#pragma once
// What nck.cycle does in the HAL thread, apart from HAL itself: take the
// input pins into a TickInput, relay the commands nck-hal queued in the
// shared Link into the kernel's own queues, run Kernel::tick() once, and
// write the output pins, the events and the feedback back. Allocation-free
// after build(); the pins are plain pointers (HAL's hal_bit_t,
// hal_float_t, hal_u32_t and hal_s32_t are these types), so a unit test can
// run it without HAL (tests/unit/hal).
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "hal/api_controls.hpp"
#include "hal/link.hpp"
#include "nck/config/machine.hpp"
#include "nck/kernel/kernel.hpp"

namespace nck::hal {

// A pin is the address of HAL's pointer to the pin's value: `net` points it
// at the signal, so it is followed every cycle.
using PinBit = volatile bool**;
using PinFloat = volatile double**;
using PinU32 = volatile std::uint32_t**;
using PinS32 = volatile std::int32_t**;

struct AxisPins {  // nck.axis.<name>.*
  PinFloat pos_cmd, pos_fb, following_error;
  PinBit enable, amp_fault, home_sw, limit_pos, limit_neg;
  PinBit homed;  // out: the kernel's homed state of the axis (P-AXIS-00277, G74)
};
// An axis whose drive is CiA 402 (kenngr.antr_typ 8): its words, beside
// pos-cmd (target position) and pos-fb (actual position).
struct CiaPins {  // nck.axis.<name>.cia-*, vel-cmd, vel-fb
  PinU32 controlword, statusword;
  PinS32 opmode, opmode_display;
  PinFloat vel_cmd, vel_fb;
};
struct ChannelPins {  // nck.channel.<n>.*
  PinBit cycle_start, feedhold, reset, single_step, optional_stop, done;
  PinFloat feed_override, rapid_override, path_velocity;
  PinU32 skip_mask;
  PinS32 program_state, block_line, status;
};
struct SpindlePins {  // nck.spindle.<name>.*
  PinFloat speed_cmd_rpm, pos_cmd_deg, speed_in_rpm, revolutions;
  PinBit feedback_valid, orient, at_speed;
  PinBit homed;  // out: the spindle's reference is known (G74)
  PinBit amp_fault;  // in: its amplifier fault (TickInput::axes of its axis list)
  int axis_list = -1;  // its machine axis list, -1 none
  // io: nck asks the encoder to reset at its next index (G33 waits for the
  // zero mark), the encoder clears it. Used only while netted: the pin then
  // no longer points at its own storage, `unwired` (taken when it was made).
  PinBit index_enable = nullptr;
  const volatile bool* unwired = nullptr;
  bool index_wired() const noexcept { return index_enable != nullptr && *index_enable != unwired; }
  // in: the PLC's controls of the spindle (the HLI's spindle control)
  PinFloat override_pct = nullptr;  // %, 100 unless set
  PinBit feedhold = nullptr, stop_at_end = nullptr;
  PinBit reset = nullptr;  // the HLI's spdl_reset: its rising edge resets the spindle
};
// A spindle command from the PLC past the NC program (FCT-S1 2.9, the HLI's
// ext_to_ipo): M3/M4/M5/M19 with its speed and position, handed over on
// the request's rising edge; `done` once the kernel acknowledged it.
struct PlcSpindleCommandPins {  // nck.spindle.<name>.plc-cmd-*
  PinS32 m;
  PinFloat rpm, pos_deg;
  PinBit request, done;
};
// A spindle whose drive is CiA 402: its words and the drive's own
// (continuous, never wrapped) target and actual position, deg and deg/s.
// A conventional drive (antr_typ 1): its velocity set point only.
struct SpindleDrivePins {  // nck.spindle.<name>.cia-*, drive-*, vel-cmd
  CiaPins words;
  PinFloat pos_cmd, pos_fb;
  int drive = -1;  // its machine axis list (the drive slot); -1: no drive the NC talks to
  bool cia402 = false;  // that drive is CiA 402 (else conventional)
};
inline constexpr std::size_t kPlcSlots = 8;
struct PlcPins {  // nck.plc.<k>.*
  PinBit request, ack;
  PinS32 kind, number, channel;
  PinFloat value;
};
struct MachinePins {  // nck.*
  PinBit estop, machine_on, watchdog, error;
  PinU32 error_id, cycles;
  // Kernel::tick()'s own time in the clocks of HAL's `nck.cycle.time`
  // (rtapi_get_clocks: the TSC on x86), and those clocks per microsecond
  // measured over the run: nck.cycle.time - nck.tick-time is the
  // component's own share (docs/hal.md, "What a cycle costs").
  PinS32 tick_time;
  PinFloat clocks_per_us;
};

// The clocks a cycle is timed with: HAL's (rtapi_get_clocks, rtapi_get_time)
// in nck.so; none in a unit test (then the timing pins stay 0).
struct CycleClocks {
  long long (*clocks)() = nullptr;  // CPU clocks
  long long (*ns)() = nullptr;      // nanoseconds
};

struct AxisRef {  // one nck.axis.* pin group: its channel and channel axis
  std::size_t channel = 0, axis = 0;
  std::string name;
  int drive = -1;  // its machine axis list (the drive slot) when the NC talks to its drive (antr_typ 8 or 1)
  bool cia402 = false;  // that drive is CiA 402 (else conventional: a velocity set point only)
  int machine = -1;  // its machine axis list (TickInput::axes: amplifier fault, limit switches)
};

class Cycle {
 public:
  // Builds the kernel from the machine nck-hal packed into `link` (may
  // allocate; runs in the module's load function). The error text names an ID.
  bool build(Link& link, std::string& error);

  const config::Machine& machine() const { return *machine_; }
  const std::vector<AxisRef>& axes() const { return axes_; }
  std::size_t channel_count() const { return machine_->channels.size(); }
  std::size_t spindle_count() const { return kernel_.spindle_count(); }
  const std::string& spindle_name(std::size_t i) const { return kernel_.spindle_name(i); }
  int spindle_axis_list(std::size_t i) const { return kernel_.spindle_axis_list(i); }

  // The pins, set before the first run().
  std::vector<AxisPins> axis_pins;
  std::vector<CiaPins> cia_pins;  // beside axis_pins; words where AxisRef::cia402, vel_cmd where drive >= 0
  std::vector<ChannelPins> channel_pins;
  std::vector<SpindlePins> spindle_pins;
  std::vector<SpindleDrivePins> spindle_drive_pins;  // beside spindle_pins
  std::vector<PlcSpindleCommandPins> plc_command_pins;  // beside spindle_pins (may be empty: a test's cells)
  std::array<PlcPins, kPlcSlots> plc_pins{};
  MachinePins machine_pins{};
  CycleClocks clocks{};

  // One kernel cycle; period_ns is the HAL thread's. Never allocates or throws.
  void run(long period_ns) noexcept;

 private:
  void fail(std::uint32_t id) noexcept;
  void read_pins() noexcept;
  void read_drives() noexcept;
  void relay_commands() noexcept;
  void write_pins() noexcept;
  void hand_to_plc() noexcept;
  void show_nc_error() noexcept;
  void tick_timed() noexcept;
  void take_api_actions() noexcept;
  void ask_for_index(const kernel::Event& e) noexcept;
  void take_plc_spindle_commands() noexcept;
  void note_plc_spindle_done(const kernel::Event& e) noexcept;
  void publish_state() noexcept;

  Link* link_ = nullptr;
  std::unique_ptr<config::Machine> machine_;
  kernel::Kernel kernel_;
  std::unique_ptr<kernel::TickInput> in_;
  std::unique_ptr<kernel::TickOutput> out_;
  std::vector<AxisRef> axes_;
  std::array<kernel::Attachment, kernel::kMaxAttachments> attachments_{};
  std::array<kernel::TechRequest, kPlcSlots> plc_slots_{};  // handle kNoHandle: free
  long long first_clocks_ = 0, first_ns_ = 0;  // at the first timed cycle
  bool watchdog_ = false;
  bool failed_ = false;
  std::uint32_t nc_error_id_ = 0;  // the last NC error event's ID while a channel is in error
  std::array<bool, config::kMaxChannels> cycle_start_was_{};
  std::array<bool, config::kMaxChannels> reset_was_{};
  std::array<bool, kernel::kMaxMachineSpindles> spindle_reset_was_{};
  std::array<bool, kPlcSlots> ack_was_{};
  std::array<ApiChannelControls, config::kMaxChannels> api_{};  // nck-hal --serve's operator
  std::array<ApiSpindleControls, kernel::kMaxMachineSpindles> api_spindles_{};
  std::array<bool, kernel::kMaxMachineSpindles> plc_request_was_{}, plc_command_pending_{};
};

}  // namespace nck::hal
