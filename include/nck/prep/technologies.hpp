#pragma once
// Preparation's list of technologies with a home of their own: adding one
// is one line here (docs/architecture.md, "Adding a technology").
#include "nck/distctrl/prep_unit.hpp"
#include "nck/prep/technology_units.hpp"

namespace nck::prep {

using PrepTechnologies = TechnologyUnits<DistUnit>;

}  // namespace nck::prep
