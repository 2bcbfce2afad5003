#pragma once
// Manual mode: jogging path axes (docs/operating.md "Manual mode"). A
// continuous jog runs an axis in one direction at a speed until it is
// released; an incremental jog moves it by one step per press. Each jogged
// axis ramps up and down with its manual-mode acceleration (at most a_max)
// and brakes so that it stands at its software limit at the latest, never
// beyond it (warning 930721 when the limit stopped it).
//
// The unit only computes each axis's travel per cycle; the channel adds it
// to the axis's manual offset (the handwheel unit), so a jog is kept for
// the program as G201 handwheel travel is (docs/decisions.md, "Measuring,
// manual mode, jog and handwheel").
#include <array>
#include <cstdint>

#include "nck/core/axes.hpp"
#include "nck/core/rapid_override.hpp"
#include "nck/kernel/tick_io.hpp"
#include "cycle.hpp"

namespace nck::kernel {

// One axis's manual-mode settings (setup; config::AxisConfig).
struct JogAxisSettings {
  double speed_mm_s = 16.666;            // continuous jog without a speed (P-AXIS-00077)
  double increment_speed_mm_s = 16.666;  // incremental jog (P-AXIS-00076)
  double max_speed_mm_s = 166.666;       // no jog faster (P-AXIS-00213, P-AXIS-00212)
  double a_max_mm_s2 = 1000;             // ramps and braking (P-AXIS-00009, P-AXIS-00008)
  double sw_limit_neg_mm = -1e300;       // software limits of the machine position
  double sw_limit_pos_mm = 1e300;
};

class JogUnit {
 public:
  // setup: the settings of channel axis j.
  void setup(std::size_t j, const JogAxisSettings& s) noexcept {
    if (j < kMaxAxes) settings_[j] = s;
  }
  // setup: P-CHAN-00181; ACTIVE_EXTENDED puts continuous jogs under the rapid override.
  void set_rapid_override_mode(RapidOverrideMode m) noexcept { rapid_mode_ = m; }
  // A cycle starts (before take()). rt
  void begin_cycle() noexcept {
    stopped_last_cycle_ = stopping_now_;
    stopping_now_ = 0;
  }
  // Takes request r, which the channel allows (a stop is always allowed). rt
  void take(const JogRequest& r, Cycle& cy) noexcept;
  // This cycle's travel of every jogged axis, from its machine set point
  // position_mm now (before the travel); axes not jogged get 0. rt
  void step(const AxisArray& position_mm, AxisArray& travel_mm, Cycle& cy) noexcept;
  bool moving() const noexcept { return active_ != 0; }
  bool moving(std::size_t j) const noexcept { return j < kMaxAxes && ((active_ >> j) & 1u) != 0; }
  // Reset: every jog is released and brakes within a_max.
  void release_all() noexcept;

 private:
  struct AxisJog {
    JogRequest::Kind kind = JogRequest::Kind::none;
    std::int8_t direction = 1;
    double wanted_mm_s = 0;  // 0 once released: brake to standstill
    double v_mm_s = 0;       // signed along `direction`
    double left_mm = 0;      // increment: distance still to go along `direction`
  };
  double axis_step(std::size_t j, double position_mm, Cycle& cy) noexcept;
  void end(std::size_t j, bool at_limit, Cycle& cy) noexcept;

  std::array<JogAxisSettings, kMaxAxes> settings_{};
  RapidOverrideMode rapid_mode_ = RapidOverrideMode::not_used;
  std::array<AxisJog, kMaxAxes> jogs_{};
  std::uint32_t active_ = 0;  // bit j: axis j is jogged
  std::uint32_t stopping_now_ = 0;        // bit j: axis j's jog ended in this cycle
  std::uint32_t stopped_last_cycle_ = 0;  // ... in the cycle before
  static_assert(kMaxAxes <= 32, "active_ holds one bit per axis");
};

}  // namespace nck::kernel
