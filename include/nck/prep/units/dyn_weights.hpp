#pragma once
// The program's dynamic weightings of the path axes (TF5200 G130...G134,
// G233): factors on the configured accelerations and ramp times.
//   G130 X.. / G131=..  a_beschl and a_brems of feed moves, up to a_w_max
//   G132 X.. / G133=..  the four feed ramp times, tr_w_min ... 4294.967295 s
//   G134=..             tr_geom;  G233=..  every ramp time of G0 (tr_grenz),
//                       both tr_min ... 4294.967295 s
// Each programming weights the configured value, never the weighting in
// force, and sets the axes it does not name back to 100 %. A weighted value
// beyond its range is limited to it, each value of each axis on its own,
// with a warning at the block (TF5200 120033...120630); the programmed
// factor stays in force for the values it leaves in range. Program start
// (a new planner) and #SLOPE DEFAULT restore 100 % everywhere. The ramp
// times matter under TRAPEZ/SIN2/HSC only; the accelerations under every
// profile (STEP uses a_beschl/a_brems too). Setup side.
#include <array>
#include <cstddef>
#include <vector>

#include "nck/core/diagnostic.hpp"
#include "nck/nc/block.hpp"
#include "nck/prep/units/axis_table.hpp"
#include "nck/prep/weight_scale.hpp"

namespace nck::prep {

class DynWeights {
 public:
  // The limits of the table's axes are kept (the table is read-only).
  explicit DynWeights(const AxisTable& axes);

  // The block's weightings: one warning per axis and kind for the values
  // they take beyond their limits (limited, the weighting still applies).
  std::vector<Diagnostic> apply(const nc::Block& b, const AxisTable& axes, const config::ChannelConfig& channel);
  // Whether any factor differs from 1.
  bool active() const { return active_; }
  // The axis table's G1/G2/G3 (rapid false) or G0 dynamics, weighted and limited.
  void weigh(AxisDynamicsArray& dyn, bool rapid) const;
  WeightScale scale() const;
  double acc_factor(std::size_t j) const { return acc_[j]; }
  double ramp_factor(std::size_t j) const { return ramp_[j]; }

 private:
  void restore();
  void update_active();
  // The limited values of the weightings block b programs, as warnings.
  std::vector<Diagnostic> limited_values(const nc::Block& b, const AxisTable& axes,
                                         const config::ChannelConfig& channel) const;
  // The factor axis j's larger feed acceleration gets (acc_ limited to a_w_max).
  double acc_used(std::size_t j) const;

  std::size_t n_axes_ = 0;
  std::array<WeightLimits, kMaxAxes> limits_{};
  AxisArray a_along_{};       // the larger feed acceleration, as configured
  AxisArray acc_{}, ramp_{};  // per axis (G130/G131, G132/G133)
  double geom_ = 1.0;         // G134
  double rapid_ramp_ = 1.0;   // G233
  bool active_ = false;
};

}  // namespace nck::prep
