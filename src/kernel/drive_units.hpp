#pragma once
// The kernel's side of the machine's CiA 402 drives (kenngr.antr_typ 8,
// not simulated by P-AXIS-00790): one cia402::Master per drive, run each
// cycle before the channels. It writes controlword and mode of operation,
// reads the statusword, and reports to the channels whether all drives are
// in operation enabled (the programs wait until they are) and the first
// drive problem of the cycle: a drive that does not reach operation
// enabled in its time (antr.enable_timeout_ms), or a fault of a drive
// that was enabled. Set points are copied after the channels ran.
//
// A conventional drive (kenngr.antr_typ 1) has no state machine: it is
// always ready, and its velocity set point closes the position loop in
// the NC, the set point's velocity plus kv (P-AXIS-00099) times the
// following error of the last set point.
//
// A spindle's drive changes its mode with the spindle (the state graph of
// FCT-S1 for digital drives): cyclic synchronous velocity while a
// speed-controlled spindle turns or stops, cyclic synchronous position
// while it positions (M19, gear change, C axis), and homing mode while G74
// lets the drive home (cia402::DriveHoming).
#include <array>
#include <cstdint>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/drives/cia402.hpp"
#include "nck/drives/cia402_homing.hpp"
#include "nck/kernel/tick_io.hpp"

namespace nck::kernel {

// What the drives tell the channels in one cycle.
struct DriveReport {
  bool ready = true;            // every CiA 402 drive is in operation enabled
  ErrorId error{};              // valid when axis >= 0
  std::int8_t axis = -1;        // machine axis list index of the drive at fault, -1 none
  std::uint64_t homed = 0;      // bit i: axis list i's drive ended its homing in this cycle
};

class DriveUnits {
 public:
  // setup: one slot per CiA 402 axis list (index < drives::kMaxDrives).
  void configure(const config::Machine& m, double cycle_s);
  bool empty() const noexcept { return slots_.empty(); }
  // Before the channels: the state machines' step. enabled false (E-stop
  // or machine off at standstill): every drive is taken out of operation,
  // which is no fault; the programs wait for enable again. rt
  // A drive that reports another mode of operation is a `drive` event.
  DriveReport step(const TickInput& in, TickOutput& out, bool enabled = true) noexcept;
  // After the channels: a path axis's set point (drive position, mm /
  // deg) and its velocity from the last one; wants_homing: G74 lets its
  // CiA 402 drive home itself (the set point then stays at the drive's
  // actual position). rt
  void write_set_point(std::size_t axis_index, double pos, bool wants_homing, const TickInput& in,
                       TickOutput& out) noexcept;

  // A spindle's drive (machine axis list index; nothing for another).
  struct SpindleCycle {
    drives::cia402::Mode mode;  // what the spindle's state asks for (CSV or CSP)
    double step_deg;            // its set point's increment this cycle (drive sense)
    bool wants_homing;          // G74: the spindle stands and waits for its drive to home
  };
  // A spindle's conventional drive, after the spindles ticked: its velocity
  // set point (deg/s, drive sense; the kernel closes the position loop in
  // it) and the set-point position beside it; 0 while not powered. rt
  void write_spindle_velocity(std::size_t axis_index, double pos_deg, double vel_deg_s, TickOutput& out) noexcept;
  // After the spindles ticked: mode, controlword's homing start and set
  // points. The target position is the drive's own, continuous (never
  // wrapped): it moves by the spindle's increments from where the drive
  // stood at enable or where it homed. rt
  void write_spindle(std::size_t axis_index, const SpindleCycle& c, const TickInput& in, TickOutput& out) noexcept;
  // The drive homed in this cycle's step: its actual position is the
  // spindle's from now on. rt
  bool homing_attained(std::size_t axis_index) const noexcept;
  // How far the drive is behind its target (its following error as the
  // NC sees it, drive sense), for the spindle's feedback. rt
  double lag(std::size_t axis_index, const TickInput& in) const noexcept;
  // The operator's reset: a drive at fault is reset (the goal asks for power again). rt
  void on_reset() noexcept;

 private:
  struct Slot {
    std::uint8_t axis = 0;                   // machine axis list index
    bool conventional = false;               // antr_typ 1: velocity set point, loop closed here
    double kv_1_s = 0;                       // conventional: position-loop gain
    drives::cia402::Master master;
    drives::cia402::Mode mode = drives::cia402::Mode::cyclic_sync_position;
    std::uint32_t timeout_cycles = 1000;
    bool reached = false;                    // operation enabled was reached since the last power-up
    bool reported = false;                   // its problem was reported (once until a reset)
    // Drive-controlled homing (G74):
    drives::cia402::DriveHoming homing;
    bool wants_homing = false;               // last written: G74 waits for the drive
    bool homing_attained = false;            // in this cycle's step
    std::uint32_t homing_timeout_cycles = 0;
    // Every drive:
    double target_pos = 0;                   // the last set point written (a spindle drive's own count, deg)
    std::int8_t mode_shown = 0;              // the last mode_display reported in an event
  };
  Slot* slot_of(std::size_t axis_index) noexcept;
  const Slot* slot_of(std::size_t axis_index) const noexcept;
  ErrorId step_homing(Slot& s, const drives::DriveFeedback& fb, bool in_operation) noexcept;
  // The cycle's mode and homing start bit: homing mode while the drive
  // homes (true), else `follow` (the mode that follows the NC's set point).
  bool command_homing(Slot& s, bool wants_homing, drives::cia402::Mode follow, drives::DriveCommand& cmd) noexcept;

  std::vector<Slot> slots_;
  std::array<std::int8_t, drives::kMaxDrives> slot_index_{};  // axis list -> slots_, -1 none
  double cycle_s_ = 0.001;
};

}  // namespace nck::kernel
