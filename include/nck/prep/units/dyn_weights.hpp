#pragma once
// The program's dynamic weightings of the path axes (TF5200 G130...G134,
// G233): factors on the configured accelerations and ramp times.
//   G130 X.. / G131=..  a_beschl and a_brems of feed moves, up to a_w_max
//   G132 X.. / G133=..  the four feed ramp times, not below tr_w_min
//   G134=..             tr_geom;  G233=..  every ramp time of G0 (tr_grenz)
// Each programming weights the configured value, never the weighting in
// force, and sets the axes it does not name back to 100 %. Program start
// (a new planner) and #SLOPE DEFAULT restore 100 % everywhere. The ramp
// times matter under TRAPEZ/SIN2/HSC only; the accelerations under every
// profile (STEP uses a_beschl/a_brems too). Setup side.
#include <cstddef>

#include "nck/nc/block.hpp"
#include "nck/prep/units/axis_table.hpp"
#include "nck/prep/units/plan_context.hpp"
#include "nck/prep/weight_scale.hpp"

namespace nck::prep {

class DynWeights {
 public:
  explicit DynWeights(std::size_t n_axes) : n_axes_(n_axes) { restore(); }

  // The block's weightings (all or none): an error at the block when a
  // weighted value would leave its range (nothing changes then).
  PlanResult apply(const nc::Block& b, const AxisTable& axes, const config::ChannelConfig& channel);
  // Whether any factor differs from 1.
  bool active() const { return active_; }
  // The axis table's G1/G2/G3 (rapid false) or G0 dynamics, weighted.
  void weigh(AxisDynamicsArray& dyn, bool rapid) const;
  WeightScale scale() const;
  double acc_factor(std::size_t j) const { return acc_[j]; }
  double ramp_factor(std::size_t j) const { return ramp_[j]; }

 private:
  void restore();
  void update_active();

  std::size_t n_axes_ = 0;
  AxisArray acc_{}, ramp_{};  // per axis (G130/G131, G132/G133)
  double geom_ = 1.0;         // G134
  double rapid_ramp_ = 1.0;   // G233
  bool active_ = false;
};

}  // namespace nck::prep
