#pragma once
// 3D distance control (SPEC 3.7): #DIST CTRL commands switch the controller
// at their block's start; every cycle it takes the sensor value (from
// TickInput or a channel variable) and its offset is added to the tool
// axis's machine set point (never to the path: the program's positions stay
// what they were).
#include <array>
#include <cstdint>

#include "nck/distctrl/controller.hpp"
#include "nck/kernel/command.hpp"
#include "cycle.hpp"

namespace nck::kernel {

class DistUnit {
 public:
  // setup: the channel's settings (dist_ctrl[0]) and cycle time.
  void setup(const distctrl::Settings& s, double dt_s) noexcept { ctrl_.setup(s, dt_s); }
  // #DIST CTRL at the start of block c (its dist, dist_axis, dist_source,
  // dist_var, dist_check_sw and software limits). rt
  Fault start(const Command& c, Cycle& cy) noexcept;
  // Every cycle, after the path: the offset for the program set point
  // pos_mm (nothing once the channel is done). rt
  Fault run(const motion::AxisVector& pos_mm, bool channel_done, Cycle& cy) noexcept;
  // At the program end block: switch off; true while the offset is still
  // being travelled out (the end block waits for it). rt
  bool wind_down() noexcept;
  // The program ended: off (an error state stays visible). rt
  void end(EndReason reason, Cycle& cy) noexcept;
  // The offset added to a machine set point m. rt
  void add_offset(motion::AxisVector& m, std::size_t n_axes) const noexcept;
  // The cycle's outputs, the offset added to the tool axis's set point. rt
  void output(ChannelOutput& out, std::size_t n_axes) const noexcept;
  distctrl::State state() const noexcept { return ctrl_.state(); }
  double offset_mm() const noexcept { return ctrl_.offset_mm(); }

 private:
  void note_state(Cycle& cy) noexcept;

  distctrl::Controller ctrl_;
  distctrl::State reported_ = distctrl::State::inactive;
  std::int8_t axis_ = -1;  // tool axis carrying the offset
  bool check_sw_ = false;
  std::int8_t source_ = 0;  // 0 the sensor in TickInput, 1 the variable var_
  std::array<char, 32> var_{};
  double sw_neg_mm_ = 0, sw_pos_mm_ = 0;
};

}  // namespace nck::kernel
