#pragma once
// The kernel's PLC side: the HLI image, the simulated PLC, the external
// spindle command queue and the scenario player.
#include "nck/plc/ext_command.hpp"
#include "nck/plc/hli.hpp"
#include "nck/plc/plc_sim.hpp"
#include "nck/plc/scenario.hpp"

namespace nck::kernel {

struct KernelPlc {
  explicit KernelPlc(const config::Machine& m)
      : sim(m.sim), hli(plc::make_hli_image(m)), map(plc::build_spindle_map(m)) {}
  plc::PlcSim sim;
  plc::HliImage hli;
  plc::SpindleMap map;
  plc::ExtCommandQueue ext;
  plc::ScenarioPlayer player;
  plc::PlcSim::AckList acks;
};

}  // namespace nck::kernel
