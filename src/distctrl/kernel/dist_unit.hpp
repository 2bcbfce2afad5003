#pragma once
// 3D distance control (channel_params_distctrl seed; docs/nc-language.md):
// #DIST CTRL commands switch the controller
// at their block's start; every cycle it takes the sensor value (from
// TickInput or a channel variable) and its offset is added to the tool
// axis's machine set point (never to the path: the program's positions stay
// what they were).
#include <array>
#include <cstdint>

#include "nck/config/machine.hpp"
#include "nck/distctrl/controller.hpp"
#include "nck/kernel/attachment.hpp"
#include "kernel/units/cycle.hpp"

namespace nck::kernel {

// A technology of the channel (kernel/technology_units.hpp names its hooks).
class DistUnit {
 public:
  using Takes = DistChange;
  // setup: the channel's settings (dist_ctrl[0]) and cycle time.
  void setup(const config::ChannelConfig& channel, double dt_s) noexcept {
    ctrl_.setup(distctrl::settings_from(channel.dist_ctrl), dt_s);
  }
  // #DIST CTRL at the start of a block. rt
  Fault start(const DistChange& c, Cycle& cy) noexcept;
  // Every cycle, after the path: the offset for the program set point
  // pos_mm (nothing once the channel is done). rt
  Fault follow(const motion::AxisVector& pos_mm, bool channel_done, Cycle& cy) noexcept {
    // Inline: off (most programs, most cycles) only a state change is news.
    if (!channel_done && ctrl_.engaged() && axis_ >= 0) return step(pos_mm, cy);
    if (ctrl_.state() != reported_) note_state(cy);
    return {};
  }
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
  Fault step(const motion::AxisVector& pos_mm, Cycle& cy) noexcept;
  void note_state(Cycle& cy) noexcept;

  distctrl::Controller ctrl_;
  distctrl::State reported_ = distctrl::State::inactive;
  std::int8_t axis_ = -1;  // tool axis carrying the offset
  bool check_sw_ = false;  // the set point stays within sw_limits_mm_ (negative, positive)
  std::array<double, 2> sw_limits_mm_{};
  DistChange::Source source_ = DistChange::Source::machine;  // the variable: var_
  std::array<char, 32> var_{};
};

}  // namespace nck::kernel
