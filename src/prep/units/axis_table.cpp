#include "nck/prep/units/axis_table.hpp"

#include <algorithm>
#include <limits>

namespace nck::prep {
namespace {

// Feed moves: accel_mm_s2 up, decel_mm_s2 down; rapid: rapid_accel_mm_s2; all capped by a_max.
// Ramp times: feed moves the four of a_beschl/a_brems, rapid tr_grenz for all.
motion::AxisDynamics feed_dynamics(const config::GearStage& g) {
  return {g.max_speed_mm_s, std::min(g.accel_mm_s2, g.a_max), std::min(g.decel_mm_s2, g.a_max),
          motion::RampTimes{g.tr_acc_up_s, g.tr_acc_down_s, g.tr_dec_up_s, g.tr_dec_down_s}, g.tr_geom_s};
}

motion::AxisDynamics rapid_dynamics(const config::GearStage& g) {
  const double a_rapid = std::min(g.rapid_accel_mm_s2, g.a_max);
  const double tr = g.tr_rapid_s;
  return {std::min(g.rapid_mm_s, g.max_speed_mm_s), a_rapid, a_rapid, motion::RampTimes{tr, tr, tr, tr}, g.tr_geom_s};
}

WeightLimits weight_limits_of(const config::GearStage& g) {
  return {g.weighted_a_max(), g.weighted_tr_min_s(), g.tr_min_s};
}

}  // namespace

AxisTable::AxisTable(const config::Machine& machine, const config::ChannelConfig& channel, std::size_t n_axes,
                     int c_axis, const config::AxisConfig* c_list)
    : n_axes_(n_axes) {
  static const config::AxisConfig kNoAxisList;  // defaults for an axis without a list
  for (std::size_t j = 0; j < n_axes_; ++j) {
    const int idx = channel.axes[j].axis_index;
    const config::AxisConfig& ax = idx >= 0 ? machine.axes[static_cast<std::size_t>(idx)] : kNoAxisList;
    const config::GearStage& g = ax.gear(ax.initial_gear_stage);
    feed_dyn_[j] = feed_dynamics(g);
    rapid_dyn_[j] = rapid_dynamics(g);
    accel_cap_mm_s2_[j] = g.a_max;
    trans_weight_[j] = g.a_trans_weight;
    weight_limits_[j] = weight_limits_of(g);
    sw_neg_mm_[j] = ax.sw_limit_neg;
    sw_pos_mm_[j] = ax.sw_limit_pos;
    home_pos_mm_[j] = g.reference_pos;
    if (idx >= 0 && ax.is_face_turning()) face_axes_ |= 1u << j;
    if (idx >= 0 && ax.homing_method() != config::HomingMethod::direct) searching_home_ |= 1u << j;
  }
  if (c_axis >= 0 && c_list) make_c_axis(static_cast<std::size_t>(c_axis), *c_list);
}

void AxisTable::make_c_axis(std::size_t j, const config::AxisConfig& list) {
  const config::GearStage& g = list.gear(list.cax_gear_stage);
  feed_dyn_[j] = feed_dynamics(g);
  rapid_dyn_[j] = rapid_dynamics(g);
  weight_limits_[j] = weight_limits_of(g);
  sw_neg_mm_[j] = -std::numeric_limits<double>::infinity();
  sw_pos_mm_[j] = std::numeric_limits<double>::infinity();
}

}  // namespace nck::prep
