#pragma once
// The simulated machine around the kernel, in ros2_control's read -> update
// -> write order: read() fills the kernel's TickInput before a cycle (the
// PLC's HLI controls and acknowledgements, external spindle commands from
// the --plc scenario, handwheel turns, the measuring probe), write() takes
// the TickOutput after it (technology functions to acknowledge, the HLI
// spindle status, the axes' set points that the probe watches). Its spindle
// drives (SpindleDrives) answer within the cycle: the kernel steps them
// through the interface it is given (Kernel::attach_drives).
//
// An integrator replaces this class with real I/O; the kernel cannot tell
// the difference. Real-time contract: read() and write() never allocate,
// lock or throw.
#include <array>
#include <cstdint>
#include <string>

#include "nck/config/machine.hpp"
#include "nck/core/fixed_vector.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/plc/hli.hpp"
#include "nck/sim/scenario.hpp"
#include "nck/sim/drive_models.hpp"
#include "nck/sim/distance_sensor.hpp"
#include "nck/sim/plc_sim.hpp"
#include "nck/sim/home_cams.hpp"
#include "nck/sim/probe.hpp"
#include "nck/sim/scenario_player.hpp"
#include "nck/sim/spindle_drives.hpp"

namespace nck::sim {

static_assert(kernel::kMaxPendingOutputs <= PlcSim::kCapacity,
              "the simulated PLC holds every output the kernel may have outstanding");

class MachineSim {
 public:
  explicit MachineSim(const config::Machine& m);  // setup
  // setup: the --plc scenario; it must stay alive while the sim runs.
  void load_scenario(const sim::Scenario& scenario);

  // rt: the machine's inputs for the cycle starting at t_s.
  void read(double t_s, kernel::TickInput& in) noexcept;
  // rt: the kernel's outputs of the cycle just computed.
  void write(const kernel::TickOutput& out) noexcept;
  // The distance sensor of channel ch delivers values from now on (before,
  // its input stays invalid: sampling it costs more than the rest of the sim).
  void switch_sensor_on(std::size_t ch) noexcept {
    if (ch < sensor_on_.size()) sensor_on_[ch] = true;
  }

  // The spindle drives, for Kernel::attach_drives (this object must outlive
  // the kernel's ticks).
  SpindleDrives& drives() noexcept { return drives_; }

  // The HLI image as the PLC sees it: controls as the PLC (scenario) set
  // them, spindle status as the CNC last wrote it.
  const plc::HliImage& hli() const noexcept { return hli_; }
  // Channel ch's holds are released at once (the scenario's auto_cycle_start, default on).
  bool auto_cycle_start(std::size_t ch) const noexcept { return ch < channels_ && auto_cycle_start_[ch]; }
  // Where channel ch holds for the caller (nck run --stop-at); no mark: none.
  void set_stop_at(std::size_t ch, const kernel::StopMark& mark) noexcept {
    if (ch < stop_at_.size()) stop_at_[ch] = mark;
  }
  // setup: channel ch's block-skip levels at program start (a live run
  // keeps the operator's), as a scenario's skip_mask line at time 0 does.
  void start_with_skip_mask(std::size_t ch, std::uint32_t mask) noexcept {
    if (ch >= channels_ || mask == 0) return;
    hli_.channel[ch].skip_mask = mask;
    skip_levels_used_ = true;
  }
  // The scenario sets block-skip levels (until then decoding needs no mask).
  bool skip_levels_used() const noexcept { return skip_levels_used_; }
  // The scenario has actions still to come.
  bool scenario_pending() const noexcept { return !player_.finished(); }
  // MDI lines of the scenario that came due, for preparation to take
  // (DryRun::prepare clears them); texts by Scenario::texts index.
  struct MdiRequest {
    std::uint32_t line = 0;  // in the scenario file
    std::uint8_t channel = 1;
    std::uint32_t text = 0;
  };
  FixedVector<MdiRequest, 64>& mdi_requests() noexcept { return mdi_requests_; }
  const FixedVector<MdiRequest, 64>& mdi_requests() const noexcept { return mdi_requests_; }
  const std::string& mdi_text(std::uint32_t i) const { return scenario_->texts.at(i); }
  const std::string& scenario_file() const { return scenario_->file; }
  // The scenario types MDI text.
  bool runs_mdi() const noexcept { return scenario_ && !scenario_->texts.empty(); }
  // Channel ch is in manual mode (the scenario's mode line).
  bool manual_mode(std::size_t ch) const noexcept { return ch < channels_ && hli_.channel[ch].manual_mode; }
  // An operator's action (nck serve, the Python session), applied in the
  // next read() after the scenario's: false when 32 already wait. MDI text
  // goes to preparation instead (DryRun::operate). rt
  bool operate(const sim::ScenarioAction& a) noexcept {
    return a.kind() != sim::ActionKind::mdi && operator_actions_.push_back(a);
  }
  // The scenario has jog lines still to come: a run goes on after its
  // program end until they have acted (jogging an ended channel).
  bool jog_pending() const noexcept { return jog_lines_left_ > 0; }

 private:
  void apply(const sim::ScenarioAction& a, kernel::TickInput& in) noexcept;
  void apply_to_spindle(const sim::ScenarioAction& a) noexcept;
  // amp_fault / limit_switch lines: one input of channel ch's path axis's machine axis.
  void set_axis_input(std::size_t ch, const act::AxisRef& axis, bool kernel::AxisSwitches::*input, bool on) noexcept;
  plc::SpindleControl* spindle_control(const act::SpindleRef& s) noexcept;  // nullptr: no HLI spindle
  static void set_variable(const act::Variable& v, kernel::ChannelInput& in) noexcept;
  static kernel::JogRequest jog_request(const act::Jog& j) noexcept;
  static kernel::JogRequest jog_request(const act::JogIncrement& j) noexcept;
  void push_jog(const kernel::JogRequest& r, kernel::ChannelInput& in) noexcept;
  static void write_channel_state(kernel::ProgramState st, plc::ChannelState& hli) noexcept;

  PlcSim plc_;
  SpindleDrives drives_;
  DriveModels drive_models_;  // the drives the NC talks to (kenngr.antr_typ 8 and 1), simulated
  plc::HliImage hli_;
  plc::SpindleMap map_;
  ScenarioPlayer player_;
  const sim::Scenario* scenario_ = nullptr;
  FixedVector<MdiRequest, 64> mdi_requests_;
  FixedVector<sim::ScenarioAction, 32> operator_actions_;
  std::array<Probe, config::kMaxChannels> probes_{};
  HomeCams home_cams_;
  std::array<DistanceSensor, config::kMaxChannels> sensors_{};
  std::array<bool, config::kMaxChannels> sensor_on_{};  // sampled only once a program needs it
  std::array<bool, config::kMaxChannels> probe_switched_{};  // in the last cycle
  std::array<bool, config::kMaxChannels> auto_cycle_start_{};  // all on (constructor)
  kernel::MachineInput machine_{};  // E-stop and machine on, as the scenario's lines set them
  std::array<kernel::AxisSwitches, drives::kMaxDrives> axes_{};  // amplifier faults and limit switches, likewise
  bool amp_fault_ = false;  // one of axes_ reports an amplifier fault
  std::array<kernel::StopMark, config::kMaxChannels> stop_at_{};
  std::size_t channels_ = 0;
  std::size_t spindles_ = 0;
  double t_s_ = 0;  // start of the cycle being computed
  bool handwheel_turned_ = false;  // in the last read: clear its travel in the next
  bool skip_levels_used_ = false;  // a skip_mask line was loaded
  std::size_t jog_lines_left_ = 0;  // jog / jog_increment lines not yet acted on
  bool jogs_given_ = false;  // in the last read: clear the requests in the next
  PlcSim::AckList acks_;
};

}  // namespace nck::sim
