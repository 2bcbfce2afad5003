#pragma once
// G96 constant cutting speed in preparation (FCT-S1 2.8.9, TF5200 G96): the
// coupling of the main spindle's speed to the face axis's radius
// (kernel::CssLink, evaluated by the channel each cycle), and the warning
// when the start speed is limited.
#include "nck/prep/units/main_spindle.hpp"
#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

class CssUnit {
 public:
  // main: the main spindle; vb_max_rpm: its top speed in the gear stage
  // planned for this block (0 = none).
  PlanResult plan(const nc::Block& b, PlannedCommand& c, const PlanContext& ctx, const MainSpindle& main,
                  double vb_max_rpm);

 private:
  bool on_ = false;       // G96 has been planned (a new S starts it anew)
  double v_m_min_ = 0;    // its cutting speed
};

}  // namespace nck::prep
