#include "homing_search.hpp"

#include <algorithm>
#include <cmath>

namespace nck::kernel {

std::uint32_t HomingSearch::searching(std::uint32_t mask) const noexcept {
  std::uint32_t out = 0;
  for (std::size_t j = 0; j < kMaxAxes; ++j)
    if ((mask >> j & 1u) != 0 && settings_[j].method != config::HomingMethod::direct) out |= 1u << j;
  return out;
}

void HomingSearch::begin(std::uint32_t mask) noexcept {
  active_ = searching(mask);
  for (std::size_t j = 0; j < kMaxAxes; ++j) {
    if ((active_ >> j & 1u) == 0) continue;
    const bool by_drive = settings_[j].method == config::HomingMethod::drive;
    axes_[j] = AxisSearch{by_drive ? Phase::drive : Phase::to_cam};
    if (by_drive) drive_homing_ |= 1u << j;
  }
}

// The searching axes brake; the G74 still waits until they stand (a reset
// ends the program then).
void HomingSearch::abort() noexcept {
  for (std::size_t j = 0; j < kMaxAxes; ++j) {
    AxisSearch& a = axes_[j];
    if (a.phase == Phase::drive) active_ &= ~(1u << j);
    if (a.phase != Phase::idle) a.phase = a.phase == Phase::drive ? Phase::idle : Phase::stopping;
  }
  drive_homing_ = timed_out_ = 0;
}

// Only an axis whose search is not over moves (the common case, no search,
// costs one test per cycle).
bool HomingSearch::moving() const noexcept {
  return active_ != 0 && std::any_of(axes_.begin(), axes_.end(), [](const AxisSearch& a) { return a.v_mm_s != 0; });
}

ErrorId HomingSearch::step(const std::array<HomingAxisInput, kMaxAxes>& in, bool hold, double dt_s,
                           AxisArray& shift_mm) noexcept {
  ErrorId error{};
  for (std::size_t j = 0; j < kMaxAxes; ++j) {
    AxisSearch& a = axes_[j];
    const HomingSearchSettings& s = settings_[j];
    const std::uint32_t bit = 1u << j;
    if (a.phase == Phase::idle) continue;
    if (a.phase == Phase::drive) {  // the drive's own timeout is DriveUnits' (940504)
      if (!in[j].drive_homed) continue;
      // The drive's reference is the machine's: its position is the axis's.
      shift_mm[j] += in[j].drive_pos_mm - in[j].machine_pos_mm;
      offset_mm_[j] = 0;
      a.phase = Phase::idle;
      active_ &= ~bit;
      drive_homing_ &= ~bit;
      continue;
    }
    if (a.phase != Phase::stopping && ++a.cycles > s.timeout_cycles) {
      a.phase = Phase::stopping;
      timed_out_ |= bit;
    }
    if (a.phase == Phase::to_cam && in[j].cam) a.cam_seen = true;
    if (a.phase == Phase::off_cam && !a.edge_seen && !in[j].cam) {
      // The cam answers the set point of the last cycle: that point is the reference.
      a.edge_seen = true;
      const double jump_mm = s.reference_mm - in[j].machine_pos_mm;
      shift_mm[j] += jump_mm;
      offset_mm_[j] -= jump_mm;
    }
    ramp(j, hold ? 0.0 : target_speed(j), dt_s);
    shift_mm[j] += a.v_mm_s * dt_s;
    if (a.v_mm_s != 0) continue;
    if (a.phase == Phase::to_cam && a.cam_seen) {
      a.phase = Phase::off_cam;
    } else if (a.phase == Phase::stopping || (a.phase == Phase::off_cam && a.edge_seen)) {
      a.phase = Phase::idle;
      active_ &= ~bit;
      if ((timed_out_ & bit) != 0) {
        timed_out_ &= ~bit;
        failed_axis_ = static_cast<std::int8_t>(j);
        error = ErrorId::KernelHomingCamNotFound;
      }
    }
  }
  return error;
}

double HomingSearch::target_speed(std::size_t j) const noexcept {
  const AxisSearch& a = axes_[j];
  const HomingSearchSettings& s = settings_[j];
  switch (a.phase) {
    case Phase::to_cam: return a.cam_seen ? 0.0 : s.to_cam * s.fast_mm_s;
    case Phase::off_cam: return a.edge_seen ? 0.0 : s.off_cam * s.off_cam_mm_s;
    default: return 0.0;
  }
}

// The speed goes to its target by at most the homing acceleration per cycle.
void HomingSearch::ramp(std::size_t j, double target_mm_s, double dt_s) noexcept {
  double& v = axes_[j].v_mm_s;
  const double dv = settings_[j].a_mm_s2 * dt_s;
  v += std::clamp(target_mm_s - v, -dv, dv);
  if (std::fabs(v) < 1e-12) v = 0;
}

}  // namespace nck::kernel
