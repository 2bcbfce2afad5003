#pragma once
// The simulated machine's CiA 402 drives: one drives::IdealDrive per axis
// list whose kenngr.antr_typ is 8 (and that P-AXIS-00790 does not simulate
// the old way): each cycle it takes the kernel's controlword and set point
// and reports its statusword and actual values. A scenario line
// (drive_fault X on|off) holds its fault input.
#include <array>
#include <cstddef>
#include <cstdint>

#include "nck/config/machine.hpp"
#include "nck/drives/ideal_drive.hpp"
#include "nck/kernel/tick_io.hpp"

namespace nck::sim {

class Cia402Drives {
 public:
  explicit Cia402Drives(const config::Machine& m);  // setup
  // rt: the statuswords and actual values of the last cycle into the kernel's input.
  void read(kernel::TickInput& in) const noexcept;
  // rt: one step of every device with the controlwords the kernel wrote.
  void write(const kernel::TickOutput& out) noexcept;
  // rt: channel ch's path axis j (0-based) has its fault input on / off.
  void set_fault(std::size_t ch, std::size_t j, bool on) noexcept;

 private:
  struct Drive {
    bool fault = false;
    drives::IdealDrive drive;
  };
  std::array<Drive, drives::kMaxDrives> drives_{};
  // The axis lists with a CiA 402 drive, in order: each cycle visits only
  // these (the 64 slots' strided flags cost a whole run 10 % without any).
  std::array<std::uint8_t, drives::kMaxDrives> present_{};
  std::size_t present_count_ = 0;
  // Channel path axis -> machine axis list, for drive_fault lines.
 public:
  // Channel ch's path axis j as a machine axis list index (-1: none). rt
  std::int16_t machine_axis(std::size_t ch, std::size_t j) const noexcept {
    return ch < config::kMaxChannels && j < kMaxAxes ? axis_of_[ch][j] : std::int16_t{-1};
  }

 private:
  std::array<std::array<std::int16_t, kMaxAxes>, config::kMaxChannels> axis_of_{};
};

}  // namespace nck::sim
