#pragma once
// A small hand-built machine for kernel tests: one channel, X Y Z.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "nck/config/machine.hpp"
#include "nck/kernel/kernel.hpp"
#include "nck/nc/block.hpp"
#include "nck/prep/channel_prep.hpp"

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
      g.max_speed_mm_s = vb_max_mm_s;
      g.rapid_mm_s = vb_max_mm_s;
      g.accel_mm_s2 = g.decel_mm_s2 = g.rapid_accel_mm_s2 = g.a_max = a_mm_s2;
    }
    m.axes.push_back(ax);
    ch.axes.push_back({names[i], i + 1, static_cast<int>(i)});
  }
  m.channels.push_back(ch);
  m.channel_data.emplace_back();
  return m;
}

// xyz_machine whose axes brake with a_emergency_mm_s2 (P-AXIS-00003; 0:
// a_max) on E-stop, an amplifier fault or a limit switch.
inline config::Machine xyz_machine_with_emergency(double vb_max_mm_s, double a_mm_s2, double a_emergency_mm_s2) {
  config::Machine m = xyz_machine(vb_max_mm_s, a_mm_s2);
  for (auto& ax : m.axes)
    for (auto& g : ax.gears) g.a_emergency = a_emergency_mm_s2;
  return m;
}

// Adds spindle S1 (logical axis 6, 6000 deg/s = 1000 rpm top speed,
// 60000 deg/s^2) to channel 1 as its main spindle; returns its axis.
inline config::AxisConfig& add_spindle_s1(config::Machine& m) {
  config::AxisConfig ax;
  ax.log_axis_nr = 6;
  ax.name = "S1";
  ax.kind = config::AxisKind::spindle;
  for (auto& g : ax.gears) {
    g.max_speed_mm_s = 6000;
    g.accel_mm_s2 = g.decel_mm_s2 = g.rapid_accel_mm_s2 = g.a_max = 60000;
  }
  m.axes.push_back(ax);
  config::ChannelSpindle sp;
  sp.name = "S1";
  sp.log_axis_nr = 6;
  sp.axis_index = static_cast<int>(m.axes.size() - 1);
  m.channels[0].spindles.push_back(sp);
  m.channels[0].main_spindle_ax_nr = 6;
  return m.axes.back();
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

// A block with one command for add_spindle_s1's S1: M3/M4/M5/M19, its
// speed, its M19 position, or G74 (homing).
inline nc::Block spindle_block(std::uint32_t line, nc::SpindleM m, std::optional<double> rpm = {},
                        std::optional<double> pos = {}, bool g74 = false) {
  nc::Block b;
  b.line = line;
  nc::SpindleCommand c;
  c.name = "S1";
  c.target = "S1";
  c.spindle_index = 0;
  c.m = m;
  c.rev_rpm = rpm;
  c.pos_deg = pos;
  c.g74 = g74;
  b.spindles.push_back(c);
  return b;
}

inline nc::Block end_block(std::uint32_t line) {
  nc::Block b;
  b.line = line;
  b.m = {30};
  b.program_end = true;
  return b;
}

// A kernel with one preparation per channel that takes hand-made blocks
// instead of decoding a program.
struct KernelRig {
  explicit KernelRig(const config::Machine& machine) : m(std::make_unique<config::Machine>(machine)) {
    EXPECT_TRUE(k.configure(*m));
    // Depth 0: each block reaches the kernel at once and ends at standstill.
    for (auto& c : m->channels) c.lookahead_blocks = 0;
    for (std::size_t ch = 0; ch < m->channels.size(); ++ch) preps.emplace_back(*m, ch, "", store, prep::PrepOptions{});
  }
  void push_block(std::size_t ch, const nc::Block& b) {
    EXPECT_TRUE(preps[ch].prepare(b, k.commands(ch)));
  }
  const std::string& message(std::uint32_t index) const { return store.messages.at(index); }

  std::unique_ptr<config::Machine> m;
  Kernel k;
  prep::PlanStore store;
  std::vector<prep::ChannelPrep> preps;
};

}  // namespace nck::kernel::testing
