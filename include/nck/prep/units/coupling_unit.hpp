#pragma once
// Synchronous operation in preparation (spindle_link seed, FCT-S1 2.8.3,
// TF5200 #SET AX LINK): #SET AX LINK / #ENABLE AX LINK / #DISABLE AX LINK become
// kernel::LinkCommand; while a spindle group is enabled, the master's speed,
// M3/M4/M5 and M19 are commanded to its slaves in the same block; path-axis
// slaves follow their master (the kernel moves them every cycle; the planned
// position follows here so later blocks start where they stand).
#include <cstdint>
#include <vector>

#include "nck/prep/ax_link_groups.hpp"
#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

class CouplingUnit {
 public:
  // spindles: the kernel spindle index of each of the channel's spindles.
  CouplingUnit(const config::ChannelConfig& channel, const std::vector<std::int8_t>& spindles);

  // The block's coupling commands and its rules (a slave is moved by its master only).
  PlanResult plan(const nc::Block& b, PlannedCommand& c, PlanContext& ctx);
  // b with the spindle functions of enabled masters also programmed for
  // their slaves (in scratch when there are any).
  const nc::Block& with_slaves(const nc::Block& b, nc::Block& scratch, const config::ChannelConfig& channel) const;
  // M30 / M2: the planning of this program ends the links.
  void end_program(const nc::Block& b);
  // Where the slaves stand once the block has run: as the kernel moves them.
  void follow(PlanContext& ctx) const;

 private:
  PlanResult plan_hash(const nc::Block& b, PlannedCommand& c, PlanContext& ctx);

  struct AxisFollow {
    int group = 0;
    int slave = 0, master = 0;  // channel axis indices
    double base_slave_mm = 0, base_master_mm = 0, ratio = 1;
  };
  int configured_main_spindle_ = -1;          // channel spindle index (P-CHAN-00051)
  AxLinkGroups groups_;
  std::vector<std::int8_t> kernel_spindles_;  // kernel index per channel spindle
  std::vector<AxisFollow> axis_follow_;
};

}  // namespace nck::prep
