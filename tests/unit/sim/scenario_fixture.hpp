#pragma once
// A two-channel machine (S1, S2 in channel 1 with S2 the main spindle; S3 in
// channel 2) and a scenario parsed and resolved against it.
#include <string_view>

#include "nck/sim/scenario.hpp"

namespace nck::sim::testing {

inline config::Machine machine() {
  config::Machine m;
  m.channels.resize(2);
  auto& c1 = m.channels[0];
  c1.spindles.resize(2);
  c1.spindles[0].name = "S1";
  c1.spindles[0].log_axis_nr = 6;
  c1.spindles[1].name = "S2";
  c1.spindles[1].log_axis_nr = 7;
  c1.main_spindle_ax_nr = 7;  // "S" is S2 at start
  auto& c2 = m.channels[1];
  c2.number = 2;
  c2.spindles.resize(1);
  c2.spindles[0].name = "S3";
  c2.spindles[0].log_axis_nr = 8;
  c2.main_spindle_ax_nr = 8;
  return m;
}

struct Fixture {
  config::Machine m = machine();
  plc::SpindleMap map = plc::build_spindle_map(m);
  Diagnostics diags;
  Scenario sc;
  explicit Fixture(std::string_view text) {
    sc = parse_scenario(text, "t.plc", diags);
    resolve_spindles(sc, m, map, diags);
  }
};

}  // namespace nck::sim::testing
