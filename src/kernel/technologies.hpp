#pragma once
// The kernel's list of technologies with a home of their own: adding one is
// one line here (docs/architecture.md, "Adding a technology").
#include "distctrl/kernel/dist_unit.hpp"
#include "technology_units.hpp"

namespace nck::kernel {

using ChannelTechnologies = TechnologyUnits<DistUnit>;

}  // namespace nck::kernel
