#pragma once
// Continuous path in preparation (docs/decisions.md, "Continuous path and
// corner blending"): what the look-ahead needs of each motion block — whether
// it must end at standstill, how fast the path may pass into it from the motion
// planned before it, and which corners may be blended. Owns the last planned
// motion and each axis's velocity budget for a kink.
#include <array>

#include "nck/prep/lookahead_window.hpp"
#include "nck/prep/units/axis_table.hpp"
#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

class CornerUnit {
 public:
  // setup: after the C axis (if any) has its data in `axes`.
  CornerUnit(const AxisTable& axes, std::uint32_t cycle_time_us);

  // The axes' feed dynamics and kink budgets, for corner blending (setup).
  BlendAxes blend_axes(const AxisTable& axes) const;
  // The feed dynamics changed (G130/G131): the kink budgets of feed moves
  // follow the weighted accelerations (what is left of a_max).
  void set_feed_dynamics(const AxisTable& axes, const AxisDynamicsArray& feed);
  // Motion c of block b has been planned: its exact stop, blending and entry limits.
  void note_transition(const nc::Block& b, PlannedCommand& c, bool rapid, const PlanContext& ctx);

 private:
  motion::AxisVector machine_tangent(const PlannedCommand& c, bool at_end, std::size_t n_axes) const;
  motion::AxisVector machine_curvature(const PlannedCommand& c, bool at_end, std::size_t n_axes) const;
  double start_acceleration(const PlannedCommand& c, const PlanContext& ctx) const;
  using Budget = std::array<double, kMaxAxes>;
  void pass_kink(PlannedCommand& c, const Budget& dv, const Budget& through_dv, double cruise_mm_s, bool jerk,
                 const PlanContext& ctx);
  static double kink_pass_acceleration(const motion::AxisVector& t_in, const motion::AxisVector& t_out, double v_mm_s,
                                       const PlanContext& ctx, double dt_s);

  // The last planned motion, for the corner into the next one.
  struct LastMotion {
    bool valid = false;
    motion::AxisVector tangent{};  // at its end, machine axes
    motion::AxisVector curvature{};  // there too (1/mm, towards the centre)
    std::array<double, kMaxAxes> corner_dv{}, through_dv{};
    double cruise_mm_s = 0;
    double a_dec_mm_s2 = 0;  // along its path
    double braking_step_mm_s = 0;  // how much faster than planned it may reach its end
    bool thread = false;     // a G33 block of a thread chain (P-CHAN-00837)
  };
  LastMotion last_{};
  double cycle_s_ = 0.001;
  // Velocity change a kink may cause per axis within one cycle. Under STEP
  // passing at speed: kKinkShare of a_max or what a_max leaves above the
  // feed accelerations, whichever is more; braking across it: only the
  // latter. Under a jerk-limited slope no more than its jerk (or
  // P-AXIS-00013) allows either.
  struct KinkBudgets {
    std::array<double, kMaxAxes> passing_mm_s{}, step_mm_s{}, jerk_limited_mm_s{};
  };
  static KinkBudgets kink_budgets(const AxisTable& axes, const AxisDynamicsArray& dyn, double dt_s);
  KinkBudgets feed_{}, rapid_{};
};

}  // namespace nck::prep
