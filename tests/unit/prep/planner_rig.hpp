#pragma once
// A planner for channel 1 of an example machine (planner and weighting tests).
#include <cstdint>
#include <string>
#include <vector>

#include "example_blocks.hpp"
#include "nck/prep/planner.hpp"

namespace nck::prep::testing {

// A planner for channel 1 of an example machine; plan() decodes a program
// text and plans every block in order, returning all commands.
struct PlannerRig {
  explicit PlannerRig(const std::string& example, std::uint32_t clamp_index = 0)
      : PlannerRig(example_machine(example), clamp_index) {}
  // m must outlive the rig.
  explicit PlannerRig(const config::Machine& m, std::uint32_t clamp_index = 0)
      : machine(m), planner(machine, 0, store, PlannerOptions{clamp_index}, spindle_indices(machine)) {}

  static std::vector<std::int8_t> spindle_indices(const config::Machine& m) {
    std::vector<std::int8_t> v;
    for (std::size_t i = 0; i < m.channels[0].spindles.size(); ++i) v.push_back(static_cast<std::int8_t>(i));
    return v;
  }

  std::vector<PlannedCommand> plan(const std::string& text) {
    std::vector<PlannedCommand> out;
    for (const nc::Block& b : decode_blocks(machine, text))
      for (const PlannedCommand& c : planner.plan(b)) out.push_back(c);
    return out;
  }

  const config::Machine& machine;
  PlanStore store;
  Planner planner;
};

}  // namespace nck::prep::testing
