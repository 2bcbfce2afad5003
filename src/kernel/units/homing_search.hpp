#pragma once
// G74 on a real drive (docs/decisions.md "Homing on a real drive"): before
// the homing block's motion, each of its axes that a real drive moves finds
// its reference.
//
// - The NC's cam search (config::HomingMethod::cam; TF5200's CNC-controlled
//   homing without zero pulse): the axis runs towards its home cam at
//   vb_refmax (kenngr.ref_richt), brakes on it, leaves it at vb_reflow or
//   vb_refmax (kenngr.fast_from_cam) against that direction (the same way
//   with kenngr.ref_ohne_rev), and the cam's edge is pos_refpkt from then
//   on. An axis that starts on the cam only leaves it.
// - A CiA 402 drive's own homing (config::HomingMethod::drive): the axis
//   stands while the drive homes in mode 6 (DriveUnits), then the drive's
//   position is the axis's.
//
// Setting the position moves no axis: the NC's coordinate of the axis
// jumps and its drive offset (drive position minus machine position) takes
// the opposite jump, so the drive's set point stays continuous. The search
// ramps with the homing acceleration (a_ref) and brakes within it when the
// channel holds, resets or the search times out.
#include <array>
#include <cstdint>

#include "nck/config/machine.hpp"
#include "nck/core/axes.hpp"
#include "nck/core/diagnostic.hpp"

namespace nck::kernel {

// One path axis's homing on a real drive (setup; config::AxisConfig).
struct HomingSearchSettings {
  config::HomingMethod method = config::HomingMethod::direct;
  std::int8_t to_cam = -1;      // direction towards the cam (kenngr.ref_richt)
  std::int8_t off_cam = 1;      // direction off it (against to_cam unless ref_ohne_rev)
  double fast_mm_s = 83.333;    // towards the cam (vb_refmax, at most vb_max)
  double off_cam_mm_s = 16.666; // off the cam (fast_from_cam ? vb_refmax : vb_reflow)
  double a_mm_s2 = 1000;        // ramps and braking (a_ref)
  double reference_mm = 0;      // pos_refpkt: the cam's edge
  std::uint32_t timeout_cycles = 60000;  // antr.homing_timeout_ms
};

// What one axis reports to the search in a cycle.
struct HomingAxisInput {
  bool cam = false;              // the home cam (TickInput::axes home_cam)
  bool drive_homed = false;      // its CiA 402 drive ended homing this cycle
  double drive_pos_mm = 0;       // the drive's actual position
  double machine_pos_mm = 0;     // the axis's machine set point of the last cycle
};

class HomingSearch {
 public:
  void setup(std::size_t j, const HomingSearchSettings& s) noexcept {
    if (j < kMaxAxes) settings_[j] = s;
  }
  // The axes of `mask` whose G74 searches (not homed by a direct move).
  std::uint32_t searching(std::uint32_t mask) const noexcept;
  // A G74 command starts: the axes of `mask` that search begin. rt
  void begin(std::uint32_t mask) noexcept;
  // One cycle of the search: `in` by channel axis; `hold` brakes the
  // search (feedhold, NC stop). Adds each axis's travel and position jump
  // to `shift_mm`. Returns a timeout's error (once, at standstill). rt
  ErrorId step(const std::array<HomingAxisInput, kMaxAxes>& in, bool hold, double dt_s,
               AxisArray& shift_mm) noexcept;
  // Reset or error: every search brakes and ends without a reference (the
  // G74 waits until the axes stand). rt
  void abort() noexcept;

  bool active() const noexcept { return active_ != 0; }  // the G74 waits for it
  bool moving() const noexcept;
  // The axes that wait for their CiA 402 drive to home (DriveUnits).
  std::uint32_t drive_homing() const noexcept { return drive_homing_; }
  // Drive position minus machine position of channel axis j, mm / deg.
  const AxisArray& drive_offsets() const noexcept { return offset_mm_; }
  // The axis whose search timed out last (channel axis), for the error's event.
  std::int8_t failed_axis() const noexcept { return failed_axis_; }

 private:
  enum class Phase : std::uint8_t { idle, to_cam, off_cam, stopping, drive };
  struct AxisSearch {
    Phase phase = Phase::idle;
    bool cam_seen = false;  // to_cam: on the cam (brakes there)
    bool edge_seen = false; // off_cam: left it (the position is set; brakes)
    double v_mm_s = 0;      // signed
    std::uint32_t cycles = 0;
  };
  double target_speed(std::size_t j) const noexcept;
  void ramp(std::size_t j, double target_mm_s, double dt_s) noexcept;

  std::array<HomingSearchSettings, kMaxAxes> settings_{};
  std::array<AxisSearch, kMaxAxes> axes_{};
  AxisArray offset_mm_{};
  std::uint32_t active_ = 0;        // bit j: axis j's search is not over
  std::uint32_t drive_homing_ = 0;  // bit j: axis j waits for its drive
  std::uint32_t timed_out_ = 0;     // bit j: brakes after its timeout
  std::int8_t failed_axis_ = -1;
  static_assert(kMaxAxes <= 32, "one bit per axis");
};

}  // namespace nck::kernel
