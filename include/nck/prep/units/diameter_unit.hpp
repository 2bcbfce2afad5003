#pragma once
// G51/G52 diameter programming (docs/nc-language.md): under G51 the positions of the
// face-turning axes (kenngr.achs_mode 0x40) are diameters about the turning
// centre — G90 words when the axis sets kenngr.durchm_prog_abs, G91 words
// when it sets diameter_prog_rel. Only the programmed words are halved: the
// offsets, the set points and the trace stay radii, and I/J/K and R are
// never diameters.
#include <cstdint>

#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

class DiameterUnit {
 public:
  DiameterUnit(const config::Machine& machine, const config::ChannelConfig& channel, std::size_t n_axes);

  // The checks of G51/G52 (and the switch itself).
  PlanResult check(const nc::Block& b, PlannedCommand& c, const PlanContext& ctx);
  // Whether axis word j of b is a diameter; its value as a radius.
  bool takes_diameter(const nc::Block& b, std::size_t j) const;
  double programmed_radius(const nc::Block& b, std::size_t j) const;

 private:
  PlanResult check_switch(const nc::Block& b, PlannedCommand& c, const PlanContext& ctx) const;

  // Bit j: axis j takes diameters under G51 with G90 / with G91.
  std::uint32_t abs_axes_ = 0, rel_axes_ = 0;
  bool on_ = false;  // G51 in force at the last planned block
};

}  // namespace nck::prep
