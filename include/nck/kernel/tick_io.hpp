#pragma once
// The data that crosses the cyclic boundary: fixed-size, no heap.
//
// Like ros2_control's read -> update -> write: whatever stands for the
// machine (the simulated one in nck/sim, or an integrator's real I/O) fills
// a TickInput before each cycle — the PLC's HLI controls and
// acknowledgements, external spindle commands, handwheel and probe, the
// spindle drives' measured actual values — and
// takes the TickOutput after it — set points, technology functions for the
// PLC, the HLI spindle status, events. The kernel sees nothing else.
#include <array>
#include <cstdint>

#include "nck/config/machine.hpp"
#include "nck/core/axes.hpp"
#include "nck/core/fixed_vector.hpp"
#include "nck/drives/drive_io.hpp"
#include "nck/kernel/event.hpp"
#include "nck/kernel/program_state.hpp"
#include "nck/plc/ext_command.hpp"
#include "nck/plc/hli.hpp"
#include "nck/spindle/drive_io.hpp"

namespace nck::kernel {

inline constexpr std::size_t kMaxEventsPerTick = 256;
inline constexpr std::size_t kMaxMachineSpindles = 32;
static_assert(kMaxMachineSpindles == plc::kMaxHliSpindles, "one HLI spindle object per kernel spindle");
// Technology functions waiting for the PLC's acknowledgement at one time;
// one more raises PlcOutputQueueFull (so the PLC side never overflows).
inline constexpr std::size_t kMaxPendingOutputs = 64;

// A channel variable the PLC writes (name upper case, NUL-terminated).
struct ChannelVariable {
  std::array<char, 32> name{};
  double value = 0;
};
inline constexpr std::size_t kMaxChannelVariables = 16;

// Where the operator wants the program to hold (stop at): at the end of
// the block with this N, on this line of the main program, the K-th block
// of the run (1-based), or the block that runs now (an event mark the
// caller recognised). Where the path cannot stop at standstill at that
// block's end within a_max, the first block end after it where it can.
struct StopMark {
  enum class Kind : std::uint8_t { none, n, line, block, now };
  Kind kind = Kind::none;
  std::int64_t value = 0;
  bool operator==(const StopMark&) const = default;
};

// The operator's jog request for one path axis (manual mode, docs/operating.md).
// A request acts in the cycle it is given; a continuous jog goes on until
// a stop request (or the software limit).
struct JogRequest {
  enum class Kind : std::uint8_t { none, continuous, increment, stop };
  Kind kind = Kind::none;
  std::int8_t axis = -1;      // channel axis index
  std::int8_t direction = 1;  // +1 / -1
  double speed_mm_s = 0;      // 0: the axis's configured jog speed (P-AXIS-00077 / 00076)
  double step_mm = 0;         // increment: the distance of one press, > 0
};
inline constexpr std::size_t kMaxJogRequestsPerTick = 8;

struct ChannelInput {
  double feed_override_pct = 100;  // HLI feed override 0..100 (more is clamped)
  double rapid_override_pct = 100;  // HLI rapid override 0..100, for G0 as P-CHAN-00181 says
  bool feedhold = false;
  bool reset = false;          // a request, acted on in this cycle
  bool optional_stop = false;  // M1 stops the program only while this is on
  // Cycle start: releases a program hold (M0/M1, single step, stop at)
  // that is in force in this cycle, or the first one the channel reaches
  // within it — one hold per cycle: a press is one step.
  bool cycle_start = false;
  // NC stop (a request, the operator's stop key): the path stops within its
  // deceleration wherever it is, and the channel holds until cycle start.
  bool stop = false;
  // Single step (the HLI's switch): hold at block ends as P-CHAN-00015 says.
  bool single_step = false;
  StopMark stop_at{};
  // The measuring probe switched during the last cycle, with the axes'
  // machine positions latched at that instant.
  bool probe_switched = false;
  AxisArray probe_latched_mcs{};
  // Handwheel travel during the last cycle per path axis, mm (G201 manual
  // mode, or any axis while manual_mode is on and the program does not move).
  AxisArray handwheel_mm{};
  // The channel's manual mode (the HLI's mode selection): the handwheel
  // moves the axes without G201, and a cycle start does not release a hold.
  bool manual_mode = false;
  // Jog requests arrived since the last cycle (acted on in this one).
  FixedVector<JogRequest, kMaxJogRequestsPerTick> jogs;
  // The distance sensor of 3D distance control: its raw value this cycle,
  // or none (a dropout).
  bool dist_sensor_valid = false;
  double dist_sensor_mm = 0;
  // Channel variables the PLC has written (SENSOR_SOURCE=VARIABLE reads one).
  FixedVector<ChannelVariable, kMaxChannelVariables> variables;
};

// The machine's own inputs (the PLC's, the HAL's pins, the API's): the
// emergency stop and machine on. Neither is a safety function — a
// machine's E-stop chain is hardware; these tell the NC to brake and to
// stop asking for motion (docs/operating.md, "E-stop and machine on").
struct MachineInput {
  // E-stop in force: every channel brakes with the axes' emergency
  // deceleration (P-AXIS-00003) and ends in error, the spindles stop, the
  // drives are disabled at standstill; starts are refused until a reset
  // after its release.
  bool estop = false;
  // Machine on: off brakes a running program as a reset does, disables the
  // drives at standstill and refuses starts until it is on again.
  bool machine_on = true;
};

// One machine axis's amplifier fault and limit switches (the HAL's pins,
// the dry run's scenario lines), by machine axis list like `drives`. Read
// for the channels' path axes (docs/decisions.md, "Amplifier faults and
// limit switches"); software limits stay as they are.
struct AxisSwitches {
  bool amp_fault = false;  // the axis's drive reports a fault (any drive type)
  bool pos_limit = false;  // the limit switch at the positive end of travel is on
  bool neg_limit = false;  // the one at the negative end
  bool home_cam = false;   // the home switch: the axis stands on its home cam (G74 on a real drive)
};

struct TickInput {
  MachineInput machine{};
  std::array<ChannelInput, config::kMaxChannels> channels{};
  std::array<plc::SpindleControl, kMaxMachineSpindles> spindles{};  // by kernel spindle index
  // What each spindle's drive measured at the start of this cycle (drive
  // sense, by kernel spindle index): the kernel judges speed reached, in
  // position and standstill from it. Not read while a Kernel::attach_drives
  // interface answers within the cycle (the simulated machine).
  std::array<spindle::DriveFeedback, kMaxMachineSpindles> spindle_measured{};
  // Outputs the PLC acknowledged since the last cycle (by the handle the
  // kernel gave them), and external spindle commands that arrived.
  FixedVector<plc::PlcAck, kMaxPendingOutputs> acks;
  FixedVector<plc::ExtSpindleCommand, plc::ExtCommandQueue::kCapacity> ext_commands;
  std::uint32_t ext_commands_lost = 0;  // arrived but did not fit (reported as PlcExtCommandQueueFull)
  // What each axis's and spindle's drive reported (by machine axis list,
  // nck/drives/drive_io.hpp); read for CiA 402 and conventional drives only.
  std::array<drives::DriveFeedback, drives::kMaxDrives> drives{};
  // Each axis's amplifier fault and limit switches (by machine axis list).
  std::array<AxisSwitches, drives::kMaxDrives> axes{};
};

enum class ChannelStatus : std::uint8_t { idle, running, waiting, ended, aborted };

// What the channel's cycle went to (time by cause, docs/outputs.md): every
// cycle of a busy channel is exactly one of these, written by the channel
// where the cycle stopped; none while the channel is done (no program).
// The application sums them; which axis binds it reads from the set points.
enum class CycleCause : std::uint8_t {
  none,          // the channel is done: no program runs
  transition,    // blocks changed without moving (zero-length blocks, program end)
  feed,          // at the programmed feed
  axis_velocity, // an axis's velocity limit caps the path below the feed
  accelerating,  // speeding up towards the feed (from standstill)
  braking,       // braking towards a stop at the block end
  corner,        // slowed for a corner or transition (end speed > 0), or back up from it
  override_,     // slowed by the feed override
  rapid,         // G0 (any phase of it)
  wait,          // waits: wait_reason says for what (dwell: WaitReason::dwell)
  hold,          // program hold: M0/M1, single step, stop at, NC stop, block search
  feedhold,      // the HLI feedhold stops the path
  starved,       // preparation late: the queue is empty or the braking reserve slows the path
};

struct ChannelOutput {
  AxisArray axis_mcs{};  // set points, mm / deg
  double path_velocity_mm_s = 0;
  double distance_to_go_mm = 0;  // the rest of the motion that runs (0 without one)
  AxisArray axis_dtg{};  // per axis: the motion's end minus the set point, mm / deg (0 without one)
  double dist_offset_mm = 0;  // 3D distance control's offset on the tool axis (0 while inactive)
  double dist_sensor_mm = 0;  // the last valid sensor value it took
  double dist_error_mm = 0;   // wanted minus measured (filtered) gap
  distctrl::State dist_state = distctrl::State::inactive;
  std::int8_t dist_axis = -1;   // the tool axis carrying the offset, -1 none yet
  ChannelStatus status = ChannelStatus::idle;
  ProgramState program_state = ProgramState::idle;
  CycleCause cause = CycleCause::none;        // what this cycle went to
  // The motion's programmed path velocity: F, under G95 / G33 the programmed
  // spindle speed x mm/rev (G96: the speed its law sets), G0 its rapid limit; 0 without motion.
  double feed_mm_s = 0;
  WaitReason wait_reason = WaitReason::plc_ack;  // cause == wait: for what
  // Homing (P-AXIS-00277), bit j = path axis j: homed, and requiring homing.
  std::uint32_t homed_axes = 0, homing_required = 0;
  // G74 on a real drive: drive position minus machine position per path
  // axis (what homing set; the drive's set point is axis_mcs plus it), and
  // the axes whose CiA 402 drive is asked to home itself (bit j).
  AxisArray axis_drive_offset{};
  std::uint32_t drive_homing_axes = 0;
  // Path axis j's set point in its drive's coordinates. rt
  double drive_pos(std::size_t j) const noexcept { return axis_mcs[j] + axis_drive_offset[j]; }
};

struct SpindleOutput {
  double set_rpm = 0;       // signed set-point speed
  double set_pos_deg = 0;   // set-point position in the modulo range
  double act_rpm = 0;       // measured actual speed (the drive's feedback)
  double drive_output = 0;  // speed command in drive units (antr.v_reso_*)
  spindle::DriveCommand drive{};  // the set point as the drive gets it (drive sense)
};

// A technology function handed to the PLC in this cycle.
struct TechRequest {
  plc::OutputHandle handle = plc::kNoHandle;
  plc::TechOutput output;
};

// What the machine's inputs made of the machine in this cycle: the
// `machine` event's payload, which reports each change.
using MachineOutput = ev::Machine;

struct TickOutput {
  double t_s = 0;  // start of the cycle just computed
  MachineOutput machine{};
  std::array<ChannelOutput, config::kMaxChannels> channels{};
  std::array<SpindleOutput, kMaxMachineSpindles> spindles{};  // by kernel spindle index
  std::array<plc::SpindleStatus, kMaxMachineSpindles> hli_spindles{};  // HLI status objects
  FixedVector<TechRequest, kMaxPendingOutputs> tech_outputs;
  FixedVector<Event, kMaxEventsPerTick> events;
  std::uint32_t events_dropped = 0;  // events that did not fit this cycle
  // What each axis's and spindle's drive gets (by machine axis list,
  // nck/drives/drive_io.hpp); written for CiA 402 and conventional drives only.
  std::array<drives::DriveCommand, drives::kMaxDrives> drives{};

  // Adds an event, or counts it as dropped when the cycle's list is full. rt
  void emit(const Event& e) noexcept {
    if (!events.push_back(e)) ++events_dropped;
  }
};

}  // namespace nck::kernel
