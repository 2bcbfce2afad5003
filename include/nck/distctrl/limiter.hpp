#pragma once
// Moves the offset towards its target no faster than v_max and with no more
// acceleration than a_max (P-CHAN-00802/00803). Towards the workpiece
// (negative offset velocity) v_weight_down / a_weight_down scale both
// (P-CHAN-00819/00820, 0 = no weighting). With use_adaptive_acceleration
// (P-CHAN-00811) the acceleration grows linearly from a_min at a distance
// error of dist_error_a_min to a_max at dist_error_a_max (P-CHAN-00812..814).
namespace nck::distctrl {

struct LimiterSettings {
  double v_max_mm_s = 5;
  double a_max_mm_s2 = 100;
  double v_weight_down = 0;  // factor, 0 = off
  double a_weight_down = 0;  // factor, 0 = off
  bool adaptive = false;
  double a_min_mm_s2 = 500;
  double err_a_min_mm = 0.1;
  double err_a_max_mm = 0.5;
};

class Limiter {
 public:
  void setup(const LimiterSettings& s, double dt_s) noexcept {
    s_ = s;
    dt_s_ = dt_s;
  }
  void reset(double pos_mm) noexcept {
    pos_mm_ = pos_mm;
    v_mm_s_ = 0;
  }
  // The acceleration allowed at this distance error (before weighting).
  double accel_for(double dist_error_mm) const noexcept;
  // One cycle towards target; returns the new offset.
  double step(double target_mm, double dist_error_mm) noexcept;
  double pos() const noexcept { return pos_mm_; }
  double v() const noexcept { return v_mm_s_; }
  // Stop where it is (a clamp at the offset limit).
  void hold_at(double pos_mm) noexcept { reset(pos_mm); }

 private:
  LimiterSettings s_{};
  double dt_s_ = 0.001;
  double pos_mm_ = 0, v_mm_s_ = 0;
};

}  // namespace nck::distctrl
