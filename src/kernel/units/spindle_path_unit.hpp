#pragma once
// The spindle-path couplings in the cycle (feed_link.hpp): each cycle the
// block's feed link becomes a velocity limit of the path profile (G95, G33,
// G63/G331 through the spindle's speed limit), the spindle follows the path
// as a tracking axis (G63, G331, G332), and under G96 the spindle speed
// follows the face axis. The planner only described the coupling; this
// unit reads a command's feed_link and css.
#include <cstdint>

#include "nck/kernel/feed_link.hpp"
#include "nck/motion/path_profile.hpp"
#include "cycle.hpp"

namespace nck::kernel {

class SpindlePathUnit {
 public:
  // At a block's start: its feed link and G96 state (none: off). rt
  void start(const FeedLink* f, const CssLink* css, ChannelContext& ctx) noexcept;
  // When a motion's body begins (an error ends the program). rt
  Fault start_motion(motion::PathProfile& path, ChannelContext& ctx) noexcept;
  // Before the path's step: the speed the coupling allows this cycle. rt
  void limit_path(motion::PathProfile& path, ChannelContext& ctx) noexcept;
  // After the path moved to s_mm at v_mm_s: the tracking spindle's set point. rt
  void follow_path(double s_mm, double v_mm_s, ChannelContext& ctx) noexcept;
  // G96, every cycle, from the machine set point (program set point pos_mm
  // plus handwheel offset manual_mm). rt
  void follow_css(const motion::AxisVector& pos_mm, const motion::AxisVector& manual_mm,
                  ChannelContext& ctx) noexcept;
  // Program end: no tracking spindle, no G96. rt
  void end(ChannelContext& ctx) noexcept;
  // The spindle tracking the path (G63, G331, G332), -1 none. rt
  std::int8_t tap_spindle() const noexcept { return tap_spindle_; }
  // G33: the path follows the spindle's actual speed on the pitch. rt
  bool threading() const noexcept { return link_.kind == FeedLinkKind::thread; }
  // G33 waits for the zero mark (+ OFFSET) before it starts. rt
  bool waits_for_zero_mark() const noexcept { return thread_waiting_; }
  // After limit_path: that wait as the other waits say theirs (a wait
  // event when it begins, its end when the mark passed). rt
  void announce_wait(Cycle& cy) noexcept;
  // The path velocity the block commands: for G95 and G33 the programmed
  // spindle speed (under G96 the one its law set) x mm/rev, else
  // `planned_mm_s` (G94, G63/G331: their feed is programmed). rt
  double commanded_feed_mm_s(double planned_mm_s, const ChannelContext& ctx) const noexcept;

 private:
  void release_tap_spindle(ChannelContext& ctx) noexcept;
  static double thread_angle_deg(const SpindleUnit& u) noexcept;

  std::int8_t tap_spindle_ = -1;  // the spindle tracking the path (G63/G331/G332), -1 none
  double tap_start_deg_ = 0;      // its set point when the block's motion began
  bool thread_waiting_ = false;   // G33: the path waits for the start angle
  bool wait_announced_ = false;   // ... and its wait event went out
  double thread_last_deg_ = 0;    // the spindle's set point one cycle ago
  FeedLink link_{};               // the block's feed link
  CssLink css_{};                 // G96 in force
};

}  // namespace nck::kernel
