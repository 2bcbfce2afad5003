#pragma once
// A channel's cyclic executor: takes planned commands from its command queue
// and runs each through its phases — outputs and waits before the motion,
// the motion (or dwell), outputs and waits after it — stopping exactly at
// each block end. What preparation needs back (G100 results, handwheel
// offsets) leaves through the feedback queue.
//
// The channel only sequences: each technology is a unit of its own
// (units/, docs/architecture.md "Kernel: technology units") that owns its
// state and gets the cycle's context (units/cycle.hpp); the channel calls
// them at a block's start, in the block's body and once per cycle, and
// raises what they report as a Fault.
//
// Continuous path: a motion ends at the velocity the look-ahead planned
// (Motion::v_end_mm_s, 0 = exact stop). When it ends at speed, the next
// block starts within the same cycle and carries on from the distance the
// path ran past the end, so the set points never pause at a transition.
// The look-ahead lets the path pass only into blocks that do not wait;
// preparation must keep the queue filled ahead of such a transition (the
// dry run does: it prepares before every cycle).
#include <array>
#include <utility>
#include <vector>

#include "nck/kernel/command.hpp"
#include "nck/kernel/queues.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/plc/hli.hpp"
#include "plc_outputs.hpp"
#include "spindle_unit.hpp"
#include "technologies.hpp"
#include "units/axis_link_unit.hpp"
#include "units/cax_unit.hpp"
#include "units/cycle.hpp"
#include "units/dwell_unit.hpp"
#include "units/handwheel_unit.hpp"
#include "units/homing_search.hpp"
#include "units/homing_unit.hpp"
#include "units/hold_unit.hpp"
#include "units/jog_unit.hpp"
#include "units/measuring_unit.hpp"
#include "units/path_unit.hpp"
#include "units/spindle_path_unit.hpp"
#include "units/sync_unit.hpp"

namespace nck::kernel {

class Channel {
 public:
  // setup: spindles holds the kernel spindle index of each channel spindle.
  Channel(std::size_t index, std::size_t n_axes, const std::vector<std::int8_t>& spindles,
          CommandQueue& commands, FeedbackQueue& feedback);

  // real-time side
  void tick(double t_s, double dt_s, const ChannelInput& in, ChannelOutput& out,
            TickOutput& sink, ChannelContext& ctx) noexcept;
  // The PLC acknowledged output h (called before tick).
  void on_ack(plc::OutputHandle h) noexcept { sync_.on_ack(h); }

  ChannelStatus status() const noexcept { return status_; }
  ProgramState program_state() const noexcept { return state_; }
  // The block the channel stands at.
  BlockRef at() const noexcept { return block_ref(current_); }
  bool done() const noexcept {
    return status_ == ChannelStatus::ended || status_ == ChannelStatus::aborted;
  }
  // The path's set point (what the program commanded) and the machine set
  // point (plus the handwheel's manual offset and distance control's offset).
  const motion::AxisVector& position() const noexcept { return path_.position(); }
  // setup: the path stands at path_mcs before the program starts.
  void start_at(const motion::AxisVector& path_mcs) noexcept { path_.position() = path_mcs; }
  motion::AxisVector machine_position() const noexcept;
  // The handwheel offset in the set point now (less than travelled while
  // #SUPPRESS OFFSETS or #MCS leaves it out).
  const motion::AxisVector& manual_offsets() const noexcept { return handwheel_.in_force_mm(); }
  std::uint8_t number() const noexcept { return number_; }
  // setup: channel axis `axis` is spindle `spindle` (kernel index) in
  // C-axis mode (#CAX); outside it the axis shows the spindle's position.
  void set_c_axis(std::int8_t axis, std::int8_t spindle) noexcept { cax_.setup(axis, spindle, n_axes_); }
  // setup: P-CHAN-00015, where single step holds.
  void set_single_step_mode(std::int8_t mode) noexcept { hold_.setup(mode); }
  // setup: P-CHAN-00181, which override scales G0 blocks (and jog).
  void set_rapid_override_mode(RapidOverrideMode mode) noexcept {
    path_.set_rapid_override_mode(mode);
    jog_.set_rapid_override_mode(mode);
  }
  // setup: channel axis j's manual-mode settings (jog speeds, a_max, software limits).
  void set_jog_axis(std::size_t j, const JogAxisSettings& s) noexcept { jog_.setup(j, s); }
  // An axis is being jogged (manual mode).
  bool jogging() const noexcept { return jog_.moving(); }
  // setup: P-CHAN-00105, enabled couplings survive M30 / M2.
  void set_preserve_links(bool on) noexcept { ax_links_.set_preserve(on); }
  // The enabled coupling groups' plan-store payloads, in enabling order.
  template <class F>
  void for_each_link(F&& f) const {
    ax_links_.for_each(std::forward<F>(f));
  }
  // setup: the technologies with a home of their own (technologies.hpp).
  void setup_technologies(const config::ChannelConfig& channel, double dt_s) { technologies_.setup(channel, dt_s); }
  const ChannelTechnologies& technologies() const noexcept { return technologies_; }
  // setup: the path's deceleration under E-stop (the smallest of its axes'
  // P-AXIS-00003, a_max where 0), mm/s^2.
  void set_emergency_decel(double a_mm_s2) noexcept { emergency_a_mm_s2_ = a_mm_s2; }
  // Homing (P-AXIS-00277): the axes that require it, the axes homed.
  HomingUnit& homing() noexcept { return homing_; }
  const HomingUnit& homing() const noexcept { return homing_; }
  // setup: channel axis j's homing on a real drive (cam search, drive homing).
  void set_homing_search(std::size_t j, const HomingSearchSettings& s) noexcept { search_.setup(j, s); }
  // An E-stop came and this channel has not been reset since its release.
  bool estop_latched() const noexcept { return estop_latched_; }
  // setup: channel axis j is machine axis `axis` (its amplifier fault and
  // limit switches in TickInput::axes; -1: none).
  void set_machine_axis(std::size_t j, std::int8_t axis) noexcept {
    if (j < kMaxAxes) machine_axis_[j] = axis;
  }
  // An axis's amplifier fault came and the channel has not been reset since it went off.
  bool amp_fault_latched() const noexcept { return amp_latched_; }

 private:
  enum class Phase : std::uint8_t { pre_wait, body, post_wait };

  // the block sequence
  void run_blocks(Cycle& cy) noexcept;
  void start(Cycle& cy) noexcept;
  void advance(Cycle& cy) noexcept;
  bool begin_body(Cycle& cy) noexcept;
  void execute(Cycle& cy) noexcept;
  void run_motion(const Motion& m, Cycle& cy) noexcept;
  void place(const Motion& m, double s_mm) noexcept;
  bool waits_done(SyncPoint phase, Cycle& cy) noexcept;
  void end_block(Cycle& cy) noexcept;
  void write_output(ChannelOutput& out, const ChannelContext& ctx) const noexcept;
  // manual mode (jog, handwheel without G201)
  void take_jogs(Cycle& cy) noexcept;
  bool jog_allowed(const JogRequest& r) const noexcept;
  void move_jogged(Cycle& cy) noexcept;
  // The program may not start or go on: the operator works in manual mode.
  bool manual_blocks_program(const ChannelInput& in) const noexcept { return in.manual_mode || jog_.moving(); }
  // Axes the handwheel moves without G201: all, in manual mode while the program does not move.
  std::uint32_t manual_axes(const ChannelInput& in) const noexcept;
  // G74 on a real drive (channel_homing.cpp): the search's cycle, and its start.
  void step_homing_search(Cycle& cy) noexcept;
  void begin_homing_search(const HomeAxes* home, Cycle& cy) noexcept;
  // the program
  void end_program(EndReason reason, Cycle& cy) noexcept;
  // keep: a spindle that follows the path and stops with it (-1 none).
  void end_spindles(EndReason reason, Cycle& cy, std::int8_t keep = -1) noexcept;
  // Raises what a unit reported (nothing once the channel is done); true
  // when it was a fault.
  bool fail(const Fault& f, Cycle& cy) noexcept;
  // axis: the machine axis the error names (none: no axis).
  void raise(ErrorId id, std::optional<std::uint32_t> message, Cycle& cy, std::optional<std::int8_t> axis = {}) noexcept;
  // Enters program state `to` (a `state` event when it changes).
  void set_state(ProgramState to, StateReason why, Cycle& cy) noexcept;
  // MDI: the operator's text wakes a channel that is done; its end or an
  // error returns the channel to idle.
  void take_mdi(Cycle& cy) noexcept;
  void follow_stop(Cycle& cy) noexcept;
  // A reset brakes the path, then ends the program; one after an error
  // leaves the error state.
  void follow_reset(Cycle& cy) noexcept;
  void clear_error(Cycle& cy) noexcept;
  // E-stop and machine on (channel_machine.cpp): what the inputs start, and
  // what they refuse.
  void follow_machine(Cycle& cy) noexcept;
  void halt_spindles(Cycle& cy) noexcept;
  // Starts are refused: E-stop latched or machine off (the ID that says so, or none).
  ErrorId refusal(const Cycle& cy) const noexcept;
  void refuse_mdi(ErrorId why, Cycle& cy) noexcept;
  // Amplifier faults and limit switches (channel_switches.cpp): what they
  // brake, and the moves into a switch that are refused.
  void follow_switches(Cycle& cy) noexcept;
  void brake_for_fault(ErrorId id, std::int8_t machine_axis, Cycle& cy) noexcept;
  // The block that just started would move an axis further into its switch: ends it (true).
  bool refuse_into_switch(Cycle& cy) noexcept;
  // A jog towards a limit switch that is on is refused with a warning (true).
  bool refuse_jog_into_switch(const JogRequest& r, Cycle& cy) const noexcept;
  // The limit switch of channel axis j in direction dir (+1 / -1) is on (as of this cycle).
  bool limit_on(std::size_t j, int dir) const noexcept {
    return j < kMaxAxes && (((dir > 0 ? pos_was_ : neg_was_) >> j) & 1u) != 0;
  }
  // An error that holds the channel in error until a reset (E-stop, amplifier fault, limit switch).
  bool machine_error() const noexcept { return estop_latched_ || amp_latched_ || limit_error_; }
  // CiA 402 drives: a drive's error brakes and aborts; the program waits for enable.
  void follow_drives(Cycle& cy) noexcept;
  bool drives_hold(Cycle& cy) noexcept;
  EndReason reset_reason() const noexcept {
    return drive_failed_ || machine_error() ? EndReason::error : EndReason::reset;
  }
  bool continues_braking() const noexcept;
  void finish_mdi(Cycle& cy) noexcept;
  void fail_mdi(Cycle& cy) noexcept;
  // Block search's restart commands: the states they enter and leave.
  void enter_restart_state(Cycle& cy) noexcept;
  void leave_restart_state(Cycle& cy) noexcept;
  // A programmed stop that applies holds the channel until cycle start.
  void stop_program(const Hold& hold, Cycle& cy) noexcept;

  // what the channel is
  CommandQueue* commands_ = nullptr;
  FeedbackQueue* feedback_ = nullptr;
  std::uint8_t number_ = 1;
  std::size_t n_axes_ = 0;
  FixedVector<std::int8_t, config::kMaxSpindles> spindles_;  // kernel index per channel spindle
  // where it is in its program
  ChannelStatus status_ = ChannelStatus::idle;
  ProgramState state_ = ProgramState::idle;
  bool active_ = false;  // `current_` is being executed
  Phase phase_ = Phase::pre_wait;
  Command current_{};
  bool dropping_mdi_ = false;  // an MDI text failed: its commands left are dropped
  // Early program ends whose `stopped` feedback went to preparation, and the
  // last of them whose dropped MDI commands were reported (CommandHead::stops_taken).
  std::uint8_t stops_sent_ = 0, discard_reported_ = 0;
  bool stopped_ = false;       // NC stop: held until cycle start
  bool resetting_ = false;     // a reset brakes the path: the program ends at standstill
  bool drive_failed_ = false;  // a drive's error brakes the path as a reset does; the program ends in error
  bool drive_wait_ = false;    // the program waits for the CiA 402 drives (a wait event was sent)
  bool estop_latched_ = false; // an E-stop came: cleared by a reset once it is released
  bool machine_was_on_ = true; // the machine-on input of the last cycle
  double emergency_a_mm_s2_ = 0;  // the path's deceleration under E-stop
  std::array<std::int8_t, kMaxAxes> machine_axis_ = [] {  // by channel axis, -1: none
    std::array<std::int8_t, kMaxAxes> a{};
    a.fill(-1);
    return a;
  }();
  bool amp_latched_ = false;   // an amplifier fault came: cleared by a reset once it is gone
  bool limit_error_ = false;   // a limit switch came on: cleared by a reset
  std::uint32_t pos_was_ = 0, neg_was_ = 0;  // the limit switches of the last cycle, by channel axis
  // What this cycle went to (time by cause), set where the cycle stops.
  CycleCause cause_ = CycleCause::none;
  WaitReason wait_reason_ = WaitReason::plc_ack;

  // its technology units (docs/architecture.md: when the channel calls them)
  SyncUnit sync_;              // outputs and waits before / after the body
  CaxUnit cax_;                // #CAX, #FACE / #CYL set points
  AxisLinkUnit ax_links_;      // #ENABLE / #DISABLE AX LINK
  ChannelTechnologies technologies_;  // #DIST CTRL ... (technologies.hpp)
  SpindlePathUnit spindle_path_;  // G95, G33, G63 / G331, G96
  HandwheelUnit handwheel_;    // G201 / G202, manual offsets
  PathUnit path_;              // profile, set point, continuous path
  MeasuringUnit measuring_;    // G100
  DwellUnit dwell_;            // G4
  HoldUnit hold_;              // single step, stop at
  JogUnit jog_;                // manual mode: jog
  HomingUnit homing_;          // homed axes, P-AXIS-00277's refusal, G74 marks
  HomingSearch search_;        // G74 on real drives: the cam search, drive homing, drive offsets
};

}  // namespace nck::kernel
