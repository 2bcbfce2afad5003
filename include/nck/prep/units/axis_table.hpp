#pragma once
// Per-axis data preparation reads from the machine configuration (setup):
// feed and rapid dynamics, software limits, acceleration caps, home
// positions and the face-turning axes. Read-only once the C axis (if any)
// has been given its C-axis data.
#include <array>
#include <cstdint>
#include <span>

#include "nck/config/machine.hpp"
#include "nck/core/axes.hpp"
#include "nck/motion/limits.hpp"

namespace nck::prep {

using AxisDynamicsArray = std::array<motion::AxisDynamics, kMaxAxes>;

// What the program's weightings may make of an axis's dynamics (P-AXIS-00292,
// 00293, 00201; config::GearStage::weighted_a_max / weighted_tr_min_s).
struct WeightLimits {
  double a_w_max_mm_s2 = 0;  // G130/G131: highest weighted a_beschl/a_brems
  double tr_w_min_s = 0;     // G132/G133: shortest weighted feed ramp time
  double tr_min_s = 0;       // G134, G233: shortest weighted tr_geom / tr_grenz
};

class AxisTable {
 public:
  // c_axis: the channel axis that is a spindle's C axis (-1: none), with
  // that spindle's axis list c_list: it moves with the data of its C-axis
  // gear stage (P-AXIS-00052) and is a modulo axis without software limits.
  AxisTable(const config::Machine& machine, const config::ChannelConfig& channel, std::size_t n_axes,
            int c_axis, const config::AxisConfig* c_list);

  std::size_t count() const { return n_axes_; }
  // G1/G2/G3 (feed) or G0 (rapid) dynamics of every axis.
  const AxisDynamicsArray& dynamics(bool rapid) const { return rapid ? rapid_dyn_ : feed_dyn_; }
  const AxisDynamicsArray& feed() const { return feed_dyn_; }
  double sw_limit_neg_mm(std::size_t j) const { return sw_neg_mm_[j]; }
  double sw_limit_pos_mm(std::size_t j) const { return sw_pos_mm_[j]; }
  double accel_cap_mm_s2(std::size_t j) const { return accel_cap_mm_s2_[j]; }
  // P-AXIS-00013 a_trans_weight as a factor (0: cycle time / ramp time).
  double trans_weight(std::size_t j) const { return trans_weight_[j]; }
  double home_pos_mm(std::size_t j) const { return home_pos_mm_[j]; }
  const WeightLimits& weight_limits(std::size_t j) const { return weight_limits_[j]; }
  // Bit j: axis j is a face-turning axis (kenngr.achs_mode 0x40).
  std::uint32_t face_axes() const { return face_axes_; }
  // Bit j: G74 of axis j searches its reference on a real drive (the
  // kernel's HomingSearch) before its motion to pos_refpkt.
  std::uint32_t searching_home() const { return searching_home_; }

 private:
  void make_c_axis(std::size_t j, const config::AxisConfig& list);

  std::size_t n_axes_ = 0;
  AxisDynamicsArray feed_dyn_{}, rapid_dyn_{};
  AxisArray sw_neg_mm_{}, sw_pos_mm_{};
  AxisArray accel_cap_mm_s2_{};  // hard cap of every acceleration (a_max)
  AxisArray trans_weight_{};     // P-AXIS-00013
  AxisArray home_pos_mm_{};      // where G74 homes the axis (reference_pos)
  std::array<WeightLimits, kMaxAxes> weight_limits_{};
  std::uint32_t face_axes_ = 0;
  std::uint32_t searching_home_ = 0;
};

}  // namespace nck::prep
