#include "nck/prep/units/axis_table.hpp"

#include <algorithm>
#include <limits>

namespace nck::prep {
namespace {

// Feed moves: a_beschl up, a_brems down; rapid: a_grenz; all capped by a_max.
motion::AxisDynamics feed_dynamics(const config::GearStage& g) {
  return {g.vb_max, std::min(g.a_beschl, g.a_max), std::min(g.a_brems, g.a_max)};
}

motion::AxisDynamics rapid_dynamics(const config::GearStage& g) {
  const double a_rapid = std::min(g.a_grenz, g.a_max);
  return {std::min(g.vb_eilgang, g.vb_max), a_rapid, a_rapid};
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
    sw_neg_mm_[j] = ax.swe_neg;
    sw_pos_mm_[j] = ax.swe_pos;
    home_pos_mm_[j] = g.pos_refpkt;
    if (idx >= 0 && ax.is_face_turning()) face_axes_ |= 1u << j;
  }
  if (c_axis >= 0 && c_list) make_c_axis(static_cast<std::size_t>(c_axis), *c_list);
}

void AxisTable::make_c_axis(std::size_t j, const config::AxisConfig& list) {
  const config::GearStage& g = list.gear(list.def_cax_gear_st);
  feed_dyn_[j] = feed_dynamics(g);
  rapid_dyn_[j] = rapid_dynamics(g);
  sw_neg_mm_[j] = -std::numeric_limits<double>::infinity();
  sw_pos_mm_[j] = std::numeric_limits<double>::infinity();
}

}  // namespace nck::prep
