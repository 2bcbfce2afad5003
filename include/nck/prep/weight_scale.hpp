#pragma once
// The spread of the dynamic weightings in force (G130...G134) over a
// channel's axes, carried by each feed motion for what is planned from the
// axis table without the block's weighted copy (blend fillets): the
// smallest and largest acceleration factor, the largest ramp and
// geometric ramp factors. All 1 when nothing is weighted.
namespace nck::prep {

struct WeightScale {
  double acc_min = 1.0, acc_max = 1.0, ramp_max = 1.0, geom = 1.0;
  bool unit() const { return acc_min == 1.0 && acc_max == 1.0 && ramp_max == 1.0 && geom == 1.0; }
};

}  // namespace nck::prep
