#pragma once
// The kernel's side of the machine's CiA 402 drives (kenngr.antr_typ 8,
// not simulated by P-AXIS-00790): one cia402::Master per drive, run each
// cycle before the channels. It writes controlword and mode of operation,
// reads the statusword, and reports to the channels whether all drives are
// in operation enabled (the programs wait until they are) and the first
// drive problem of the cycle: a drive that does not reach operation
// enabled in its time (antr.enable_timeout_ms), or a fault of a drive
// that was enabled. Set points are copied after the channels ran.
#include <cstdint>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/drives/cia402.hpp"
#include "nck/kernel/tick_io.hpp"

namespace nck::kernel {

// What the drives tell the channels in one cycle.
struct DriveReport {
  bool ready = true;            // every CiA 402 drive is in operation enabled
  ErrorId error{};              // valid when axis >= 0
  std::int8_t axis = -1;        // machine axis list index of the drive at fault, -1 none
};

class DriveUnits {
 public:
  // setup: one slot per CiA 402 axis list (index < drives::kMaxDrives).
  void configure(const config::Machine& m, double cycle_s);
  bool empty() const noexcept { return slots_.empty(); }
  // Before the channels: the state machines' step. enabled false (E-stop
  // or machine off at standstill): every drive is taken out of operation,
  // which is no fault; the programs wait for enable again. rt
  DriveReport step(const TickInput& in, TickOutput& out, bool enabled = true) noexcept;
  // After the channels: the set points (machine axis positions, mm / deg). rt
  void write_set_point(std::size_t axis_index, double pos, double vel, TickOutput& out) const noexcept;
  // The operator's reset: a drive at fault is reset (the goal asks for power again). rt
  void on_reset() noexcept;

 private:
  struct Slot {
    std::uint8_t axis = 0;                   // machine axis list index
    drives::cia402::Master master;
    drives::cia402::Mode mode = drives::cia402::Mode::cyclic_sync_position;
    std::uint32_t timeout_cycles = 1000;
    bool reached = false;                    // operation enabled was reached since the last power-up
    bool reported = false;                   // its problem was reported (once until a reset)
  };
  std::vector<Slot> slots_;
};

}  // namespace nck::kernel
