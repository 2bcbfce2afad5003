#pragma once
// The kernel: configured once (may allocate, may fail), then run cycle by
// cycle through tick(), which never allocates, throws, locks, does I/O or
// reads a clock: time comes in with the cycle count.
//
// Planned commands reach each channel through its command queue (filled by
// nck/prep on the setup side); what preparation needs back from execution
// leaves through the channel's feedback queue. Everything the machine says
// comes in with TickInput, everything for the machine goes out with
// TickOutput (nck/sim simulates the machine; real I/O can replace it).
#include <cstdint>
#include <expected>
#include <memory>
#include <string>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/kernel/queues.hpp"
#include "nck/kernel/spindle_drives.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/plc/ext_command.hpp"
#include "nck/plc/hli.hpp"
#include "nck/spindle/spindle_status.hpp"

namespace nck::kernel {

class Channel;
struct SpindleUnit;
class PlcOutputs;
class DriveUnits;

// A channel's execution state, for the final state.
struct ChannelState {
  motion::AxisVector path_mcs{};        // the path's set point (what the program commanded)
  motion::AxisVector manual_offsets{};  // handwheel offsets reached (G201)
  motion::AxisVector axis_mcs{};        // machine set point: path + handwheel
  ChannelStatus status = ChannelStatus::idle;
  ProgramState program_state = ProgramState::idle;
  BlockRef at{};  // the block the channel stands at
  distctrl::State dist_state = distctrl::State::inactive;
  double dist_offset_mm = 0;    // distance-control offset in axis_mcs
  std::uint32_t homed_axes = 0;        // bit j: path axis j is homed
  std::uint32_t homing_required = 0;   // bit j: P-AXIS-00277 set for path axis j
};

class Kernel {
 public:
  Kernel();
  ~Kernel();
  Kernel(Kernel&&) noexcept;
  Kernel& operator=(Kernel&&) noexcept;

  // setup: builds channels, spindles and queues from the machine.
  std::expected<void, Diagnostic> configure(const config::Machine& machine);
  // setup: drives that answer within the cycle (a simulated machine); they
  // must outlive the kernel's ticks. Without them (nullptr) the measured
  // values come with TickInput::spindle_measured.
  void attach_drives(SpindleDrives* drives) noexcept { drives_ = drives; }

  std::size_t channel_count() const;
  // The machine's spindles (a spindle shared by channels is one), in the
  // order of plc::build_spindle_map: kernel index = HLI spindle index.
  std::size_t spindle_count() const;
  const std::string& spindle_name(std::size_t index) const;
  // The machine axis list of spindle `index` (< drives::kMaxDrives), -1 without one.
  int spindle_axis_list(std::size_t index) const;
  const spindle::SpindleStatus& spindle_status(std::size_t index) const;
  // The spindle's HLI status object as the last tick wrote it to hli_spindles.
  plc::SpindleStatus hli_spindle_status(std::size_t index) const;
  const plc::SpindleMap& spindle_map() const;
  // The name of machine axis list `index` (kopf.log_achs_name; "" when none).
  const std::string& axis_name(std::size_t index) const;
  double cycle_time_s() const { return cycle_s_; }

  // The queues of channel ch (0-based); see nck/kernel/queues.hpp for who
  // produces and who consumes each.
  CommandQueue& commands(std::size_t ch) { return *command_queues_.at(ch); }
  FeedbackQueue& feedback(std::size_t ch) { return *feedback_queues_.at(ch); }
  ChannelState channel_state(std::size_t ch) const;
  // setup: channel ch's path stands at path_mcs before its program starts.
  void start_channel_at(std::size_t ch, const motion::AxisVector& path_mcs);
  // Which of channel ch's path axes are homed (bit j = axis j; without a
  // call: all, as the dry run assumes; no such channel: nothing). At setup,
  // or between runs of a live session before this kernel's first tick. rt
  void set_homed_axes(std::size_t ch, std::uint32_t mask) noexcept;
  // Channel ch's homed axes (bit j = path axis j; 0 for no such channel). rt
  std::uint32_t homed_axes(std::size_t ch) const noexcept;
  // setup: the message (Kernel::message index) naming axis j of channel ch
  // when its unhomed motion is refused (930740); without it, the ID's text.
  void name_unhomed_axis(std::size_t ch, std::size_t j, std::uint32_t message);
  // The coupling groups enabled in channel ch: their plan-store payloads.
  std::vector<std::uint32_t> active_links(std::size_t ch) const;

  // real-time side -------------------------------------------------------
  void tick(const TickInput& in, TickOutput& out) noexcept;

  bool all_channels_done() const noexcept;
  // Inline: preparation asks it every cycle.
  bool channel_done(std::size_t ch) const noexcept { return ch < channel_done_.size() && channel_done_[ch] != 0; }
  ProgramState program_state(std::size_t ch) const noexcept;
  // An axis of channel ch is being jogged (manual mode).
  bool channel_jogging(std::size_t ch) const noexcept;
  std::uint64_t cycles() const noexcept { return cycles_; }
  // What E-stop and machine on made of the machine, as of the last tick.
  const MachineOutput& machine_state() const noexcept { return machine_out_; }
  // Channel ch keeps an E-stop latched until its reset after the release.
  bool estop_latched(std::size_t ch) const noexcept;
  // Channel ch keeps an amplifier fault latched until its reset after it went off.
  bool amp_fault_latched(std::size_t ch) const noexcept;
  // Simulated time at the start of the next cycle.
  double time_s() const noexcept { return time_s_; }

 private:
  void take_acknowledgements(const TickInput& in, double t_s, TickOutput& out) noexcept;
  void take_spindle_controls(const TickInput& in) noexcept;
  void take_spindle_measured(const TickInput& in) noexcept;
  void take_external_commands(const TickInput& in, double t_s, TickOutput& out) noexcept;
  void run_external_commands(double t_s, TickOutput& out) noexcept;
  void hand_out_external_commands() noexcept;
  void tick_spindles(double t_s, TickOutput& out) noexcept;
  // kernel_drives.cpp: the CiA 402 drives of path axes and spindles.
  void write_drive_set_points(const TickInput& in, TickOutput& out) noexcept;
  void take_drive_homing(const TickInput& in) noexcept;
  bool take_spindle_drive(SpindleUnit& u, const TickInput& in) noexcept;
  // After the channels: standstill, the drives' enable, the `machine` event (kernel_machine.cpp).
  void follow_machine(const TickInput& in, double t_s, TickOutput& out) noexcept;

  std::unique_ptr<const config::Machine> machine_;  // own copy: channels refer into it
  std::vector<SpindleUnit> spindles_;
  std::vector<std::string> spindle_names_;
  plc::SpindleMap spindle_map_;
  plc::ExtCommandQueue ext_commands_;
  std::unique_ptr<PlcOutputs> plc_outputs_;
  SpindleDrives* drives_ = nullptr;  // not owned
  std::unique_ptr<DriveUnits> drive_units_;  // the CiA 402 drives' state machines
  std::vector<std::unique_ptr<CommandQueue>> command_queues_;
  std::vector<std::unique_ptr<FeedbackQueue>> feedback_queues_;
  std::vector<std::unique_ptr<Channel>> channels_;
  MachineOutput machine_out_{};  // E-stop and machine on: the last tick's
  std::vector<std::uint8_t> channel_done_;  // per channel: ended or aborted, as of the last tick
  double cycle_s_ = 0.001;
  std::uint64_t cycle_us_ = 1000;
  std::uint64_t cycles_ = 0;
  // The next tick's time, from integer microseconds so that times print as
  // the decimals they are; kept because it is asked for several times a cycle.
  double time_s_ = 0;
};

}  // namespace nck::kernel
