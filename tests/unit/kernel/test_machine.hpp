#pragma once
// A small hand-built machine for kernel tests: one channel, X Y Z.
#include "nck/config/machine.hpp"
#include "nck/nc/block.hpp"

namespace nck::kernel::testing {

inline config::Machine xyz_machine(double vb_max_mm_s = 500, double a_mm_s2 = 2000) {
  config::Machine m;
  m.cycle_time_us = 1000;
  config::ChannelConfig ch;
  const char* names[] = {"X", "Y", "Z"};
  for (std::uint32_t i = 0; i < 3; ++i) {
    config::AxisConfig ax;
    ax.log_axis_nr = i + 1;
    ax.name = names[i];
    for (auto& g : ax.gears) {
      g.vb_max = vb_max_mm_s;
      g.vb_eilgang = vb_max_mm_s;
      g.a_beschl = g.a_brems = g.a_grenz = g.a_max = a_mm_s2;
    }
    m.axes.push_back(ax);
    ch.axes.push_back({names[i], i + 1, static_cast<int>(i)});
  }
  m.channels.push_back(ch);
  m.channel_data.emplace_back();
  return m;
}

inline nc::Block move(std::uint32_t line, nc::Motion motion, std::optional<double> x,
                      std::optional<double> y = {}, std::optional<double> z = {},
                      double f_mm_min = 6000) {
  nc::Block b;
  b.line = line;
  b.modal.motion = motion;
  b.modal.feed_mm_min = f_mm_min;
  b.axes[0] = x;
  b.axes[1] = y;
  b.axes[2] = z;
  return b;
}

inline nc::Block end_block(std::uint32_t line) {
  nc::Block b;
  b.line = line;
  b.m = {30};
  b.program_end = true;
  return b;
}

}  // namespace nck::kernel::testing
