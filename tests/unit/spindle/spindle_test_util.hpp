#pragma once
// A spindle axis list for the interpolator tests, in internal units.
#include "nck/config/machine.hpp"
#include "nck/spindle/spindle_axis.hpp"

namespace nck::spindle::test {

inline config::AxisConfig spindle_axis_config() {
  config::AxisConfig ax;
  ax.name = "S1";
  ax.kind = config::AxisKind::spindle;
  ax.log_axis_nr = 6;
  for (auto& g : ax.gears) {
    g.accel_mm_s2 = 3000;       // deg/s^2
    g.decel_mm_s2 = 4000;
    g.a_max = 6000;
    g.max_speed_mm_s = 60000;        // 10000 rpm
    g.rapid_mm_s = 600;      // 100 rpm
    g.position_gain_1_s = 10;
    g.control_limit_deg_s = 0;    // no control limit unless a test sets one
    g.zero_speed_deg_s = 0.1;
    g.reference_pos = 0;
  }
  return ax;
}

inline config::ChannelSpindle channel_spindle() {
  config::ChannelSpindle sp;
  sp.name = "S1";
  sp.log_axis_nr = 6;
  return sp;
}

// Ticks until `done` or the step budget runs out; returns the ticks used.
template <class Done>
int run_until(SpindleAxis& s, Done done, int max_ticks, double dt = 0.001) {
  for (int i = 0; i < max_ticks; ++i) {
    if (done(s.status())) return i;
    s.tick(dt);
  }
  return max_ticks;
}

inline SpindleAxis make_spindle(const config::AxisConfig& ax, double cycle_s = 0.001) {
  SpindleAxis s;
  auto r = s.configure(&ax, channel_spindle(), cycle_s);
  (void)r;
  return s;
}

}  // namespace nck::spindle::test
