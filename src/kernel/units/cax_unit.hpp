#pragma once
// C-axis machining (#CAX, FCT-S1 §2.8.8): the main spindle is a path axis of
// the channel while C-axis mode is on. The path computes its set point like
// any axis (through #FACE / #CYL in PathUnit::place); every cycle hands it
// to the spindle, whose own interpolator then only follows (SpindleAxis
// axis mode). Outside C-axis mode the C axis shows where the spindle is, so
// that C-axis mode starts from there.
#include <cstdint>

#include "nck/kernel/attachment.hpp"
#include "cycle.hpp"

namespace nck::kernel {

class CaxUnit {
 public:
  // setup: channel axis `axis` (of n_axes) is spindle `spindle` (kernel index).
  void setup(std::int8_t axis, std::int8_t spindle, std::size_t n_axes) noexcept;
  // #CAX / #CAX OFF at the start of a block; C-axis mode starts where the
  // spindle stands (in pos_mm). rt
  Fault start(const CaxChange& c, motion::AxisVector& pos_mm, Cycle& cy) noexcept;
  // After the cycle's path step: the spindle follows C, or C shows the spindle. rt
  // (Inline: most channels have no C axis.)
  void follow(double dt_s, motion::AxisVector& pos_mm, ChannelContext& ctx) noexcept {
    if (axis_ >= 0) follow_c(dt_s, pos_mm, ctx);
  }
  // Program end: the spindle is a spindle again. rt
  void end(ChannelContext& ctx) noexcept;

 private:
  void follow_c(double dt_s, motion::AxisVector& pos_mm, ChannelContext& ctx) noexcept;
  std::int8_t axis_ = -1;     // channel index of the C axis, -1 none
  std::int8_t spindle_ = -1;  // its spindle (kernel index)
  bool on_ = false;           // #CAX in force: the path drives the spindle
  double last_deg_ = 0;       // C set point of the cycle before (for its velocity)
};

}  // namespace nck::kernel
