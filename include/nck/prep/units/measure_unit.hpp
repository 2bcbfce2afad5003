#pragma once
// G100 measuring runs and the G101/G102 measuring offset: which axis the
// simulated probe watches, the target of the last run and what it measured.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "nck/kernel/measure.hpp"
#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

class MeasureUnit {
 public:
  // c is the G100 block's planned linear move: it stops where the probe switches.
  void start_run(PlannedCommand& c, const PlanContext& ctx);
  // After a G100 run (preparation held further blocks back until it ended):
  // planning goes on from where the axes stopped. Returns the decoder's
  // V.A.MESS/MERF/MOFFS variables.
  std::vector<std::pair<std::string, double>> take_measurement(const kernel::MeasureResult& r, PlanContext& ctx);
  // G101 X<factor>..: (measured - target) * factor as an offset; G102 [X..]
  // removes it. Both act at the axis's next absolute position.
  PlanResult apply_offset(const nc::Block& b, PlannedCommand& c, PlanContext& ctx) const;

 private:
  // The last G100 run, in program coordinates (G101 reads it).
  bool any_ = false;        // a G100 run has ended
  bool triggered_ = false;  // and its probe switched
  motion::AxisVector measured_pcs_{};
  motion::AxisVector run_target_pcs_{};  // of the last run that ended
  motion::AxisVector target_pcs_{};      // of the run planned last
};

}  // namespace nck::prep
