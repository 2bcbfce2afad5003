#pragma once
// #DIST CTRL in preparation: the decoded switch (docs/nc-language.md) becomes the
// fixed-size distctrl::Switch the channel executes, with the overrides
// checked against the ranges of their channel parameters (P-CHAN-00800..00827).
#include <cstdint>

#include "nck/distctrl/dist_data.hpp"
#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

class DistUnit {
 public:
  PlanResult plan(const nc::Block& b, PlannedCommand& c, const PlanContext& ctx);
  // ON/FREEZE has been prepared in this run (the sensor is needed from now on).
  bool programmed() const { return programmed_; }

 private:
  PlanResult plan_source(const nc::Block& b, const nc::DistCtrl& d, distctrl::DistChange& change);

  bool on_ = false;            // ON (or FREEZE) programmed and not OFF since
  bool programmed_ = false;    // ON (or FREEZE) prepared at least once
  distctrl::DistChange::Source source_ = distctrl::DistChange::Source::machine;
  bool var_known_ = false;     // SENSOR_VAR given
};

}  // namespace nck::prep
