#pragma once
// The simulated machine's models of the drives the NC talks to (the axis
// lists whose kenngr.antr_typ is 8, CiA 402, or 1, conventional, and that
// P-AXIS-00790 does not simulate the old way): one drives::IdealDrive
// each. Each cycle it takes the kernel's command and reports the drive's
// answer: a CiA 402 drive its statusword and actual values, a
// conventional one the position its velocity set point reached. A
// scenario line (drive_fault X on|off) holds a CiA 402 drive's fault input.
#include <array>
#include <cstddef>
#include <cstdint>

#include "nck/config/machine.hpp"
#include "nck/drives/ideal_drive.hpp"
#include "nck/kernel/tick_io.hpp"

namespace nck::sim {

class DriveModels {
 public:
  explicit DriveModels(const config::Machine& m);  // setup
  // rt: the drives' answers of the last cycle into the kernel's input.
  void read(kernel::TickInput& in) const noexcept;
  // rt: one step of every drive with the commands the kernel wrote.
  void write(const kernel::TickOutput& out) noexcept;
  // rt: channel ch's path axis j (0-based) has its fault input on / off.
  void set_fault(std::size_t ch, std::size_t j, bool on) noexcept;
  // Channel ch's path axis j as a machine axis list index (-1: none). rt
  std::int16_t machine_axis(std::size_t ch, std::size_t j) const noexcept {
    return ch < config::kMaxChannels && j < kMaxAxes ? axis_of_[ch][j] : std::int16_t{-1};
  }

 private:
  struct Drive {
    bool fault = false;
    bool conventional = false;  // antr_typ 1: follows its velocity set point
    drives::IdealDrive drive;
  };
  double cycle_s_;
  std::array<Drive, drives::kMaxDrives> drives_{};
  // The axis lists with a drive model, in order: each cycle visits only
  // these (the 64 slots' strided flags cost a whole run 10 % without any).
  std::array<std::uint8_t, drives::kMaxDrives> present_{};
  std::size_t present_count_ = 0;
  // Channel path axis -> machine axis list, for drive_fault lines.
  std::array<std::array<std::int16_t, kMaxAxes>, config::kMaxChannels> axis_of_{};
};

}  // namespace nck::sim
