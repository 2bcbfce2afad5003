#pragma once
// Handwheel and manual offsets (G201 / G202, #SUPPRESS OFFSETS, #MCS,
// #GET MANUAL OFFSETS): handwheel turns move the axes in manual mode; the
// offset reached is travelled at a limited speed and is in each axis's
// machine set point with a share (0..1) that a motion block blends along
// its path, so nothing jumps.
#include <algorithm>
#include <cstdint>

#include "nck/kernel/attachment.hpp"
#include "nck/kernel/command.hpp"
#include "cycle.hpp"

namespace nck::kernel {

inline constexpr double kHandwheelSpeed_mm_s = 10.0;  // how fast a handwheel offset is travelled

class HandwheelUnit {
 public:
  HandwheelUnit() noexcept {
    share_.fill(1.0);
    share_start_.fill(1.0);
  }
  // A block starts: axes enter / leave manual mode, #GET MANUAL OFFSETS. rt
  void start(const ManualChange* c) noexcept;
  // Motion m (path length length_mm) reached s_mm: the share of each axis's offset. rt
  void blend(const Motion& m, double length_mm, double s_mm, std::size_t n_axes) noexcept;
  // Every cycle: follow the handwheel; at #GET MANUAL OFFSETS send the
  // offsets reached at the end of its cycle. rt
  // manual_axes: axes the handwheel moves besides those in G201 (manual
  // mode while the program does not move).
  Fault follow(Cycle& cy, std::uint32_t manual_axes = 0) noexcept {
    if (manual_axes != 0) used_ = true;
    return used_ || fetch_pending_ ? follow_offsets(cy, manual_axes) : Fault{};  // inline: most programs never use it
  }
  // A jog moved axis j by d_mm: it joins the axis's manual offset at once
  // (the jog has ramped it within a_max). rt
  void add_mm(std::size_t j, double d_mm) noexcept {
    offset_mm_[j] += d_mm;
    target_mm_[j] += d_mm;
    in_force_mm_[j] = offset_mm_[j] * share_[j];
    used_ = true;
  }
  // Axis j is in manual mode (G201).
  bool in_manual_mode(std::size_t j) const noexcept { return j < 32 && ((manual_mask_ >> j) & 1u) != 0; }
  // The offset in the set point now (less than travelled while
  // #SUPPRESS OFFSETS or #MCS leaves it out).
  const motion::AxisVector& in_force_mm() const noexcept { return in_force_mm_; }

 private:
  Fault follow_offsets(Cycle& cy, std::uint32_t manual_axes) noexcept;
  bool fetch_pending_ = false;    // #GET MANUAL OFFSETS: send them at the end of this cycle
  std::uint32_t manual_mask_ = 0;  // axes in manual mode (G201)
  bool used_ = false;              // some axis was in manual mode in this run
  motion::AxisVector offset_mm_{};  // handwheel offset reached so far
  motion::AxisVector target_mm_{};
  // Share (0..1) of the handwheel offset in each set point, when the block
  // started and now.
  motion::AxisVector share_start_{}, share_{};
  bool settled_ = true;               // share_ is 1 for the axes in settled_axes_, 0 for the others
  std::uint32_t settled_axes_ = ~0u;
  motion::AxisVector in_force_mm_{};
};

// A motion block takes the handwheel offset of its axes in or out
// (Motion::handwheel_axes) in step with its path, 0 at its start and 1 at
// its end, so the set point never jumps by the offset.
// Shares already at the targets this block blends to stay as they are
// (start + (target - start) * f is target): most blocks of most programs.
inline void HandwheelUnit::blend(const Motion& m, double length_mm, double s_mm, std::size_t n_axes) noexcept {
  if (settled_ && m.handwheel_axes == settled_axes_) return;
  const double fraction = length_mm > 0 ? std::clamp(s_mm / length_mm, 0.0, 1.0) : 1.0;
  for (std::size_t j = 0; j < n_axes; ++j) {
    const double target = (m.handwheel_axes >> j) & 1u ? 1.0 : 0.0;
    share_[j] = share_start_[j] + (target - share_start_[j]) * fraction;
  }
  settled_ = fraction == 1.0;
  settled_axes_ = m.handwheel_axes;
}

}  // namespace nck::kernel
