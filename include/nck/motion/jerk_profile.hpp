#pragma once
// Jerk-limited velocity changes along a path (the TRAPEZ and SIN2 slopes):
// closed-form phases in continuous time. The acceleration moves between
// levels in ramps whose length is proportional to the change (the full
// ramp 0 -> a takes the ramp time tr), straight (TRAPEZ: jerk a/tr) or
// along sin^2 (SIN2: peak jerk (pi/2) a/tr, the same velocity gained per
// ramp). The kernel samples a plan at its cycle times, so the set points'
// finite differences never exceed what the continuous profile does.
// Pure functions and plain data: no allocation, rt-safe.
#include <array>
#include <cstddef>

namespace nck::motion {

struct JerkLimits {
  double a_acc_mm_s2 = 0;  // speeding up (a_beschl)
  double a_dec_mm_s2 = 0;  // slowing down (a_brems)
  double tr_acc_up_s = 0;    // build-up of a_acc (tr_beschl_zu)
  double tr_acc_down_s = 0;  // reduction of a_acc (tr_beschl_ab)
  double tr_dec_up_s = 0;    // build-up of a_dec (tr_brems_zu)
  double tr_dec_down_s = 0;  // reduction of a_dec (tr_brems_ab)
  bool sin2 = false;         // sin^2 ramps instead of straight ones
  bool operator==(const JerkLimits&) const = default;
};

// Both accelerations finite and > 0, every ramp time finite and >= 0.
bool valid(const JerkLimits& l) noexcept;

struct Kinematics {
  double s_mm = 0, v_mm_s = 0, a_mm_s2 = 0;
};

// One phase: the acceleration moves from a0 to a1 in t_s (constant when
// equal). t_s may be +infinity only for a standstill (v = a = 0).
struct JerkPhase {
  double t_s = 0, a0_mm_s2 = 0, a1_mm_s2 = 0;
};

class JerkPlan {
 public:
  static constexpr std::size_t kMaxPhases = 12;

  // Empty plan starting at `start`. rt
  void reset(const Kinematics& start, bool sin2) noexcept;
  // Appends the fastest change from the plan's end state to velocity v1
  // with acceleration 0, within the limits' accelerations and jerks. rt
  void append_change(double v1_mm_s, const JerkLimits& l) noexcept;
  // Appends a constant velocity (acceleration 0) phase. rt
  void append_cruise(double t_s) noexcept;

  // State at time t (clamped to [0, duration]; beyond it the end state
  // moves on at its velocity). rt
  Kinematics at(double t_s) const noexcept;
  Kinematics end_state() const noexcept { return ends_[n_]; }
  double duration() const noexcept { return t_[n_]; }
  std::size_t phases() const noexcept { return n_; }
  const JerkPhase& phase(std::size_t i) const noexcept { return ph_[i]; }
  // Start time of phase i and the state there (i == phases(): the end). rt
  double phase_start_s(std::size_t i) const noexcept { return t_[i]; }
  const Kinematics& phase_start_state(std::size_t i) const noexcept { return ends_[i]; }
  // The first time from which the path only slows down or holds (the
  // plan's final change downwards begins); duration() when none. rt
  double braking_from_s() const noexcept;

 private:
  void push(double t_s, double a0, double a1) noexcept;

  std::array<JerkPhase, kMaxPhases> ph_{};
  std::array<Kinematics, kMaxPhases + 1> ends_{};  // state at the start of phase i (ends_[n_]: the end)
  std::array<double, kMaxPhases + 1> t_{};         // start time of phase i
  std::size_t n_ = 0;
  bool sin2_ = false;
};

// What plan_block decided.
enum class BlockPlanKind : unsigned char {
  fits,     // ends at the length with v_end (or lower) and acceleration 0
  overrun,  // cannot slow to v_end within the length: brakes on past it
  forced,   // must stop at the length: ramp times shortened to fit
};

// The plan of one block of length_mm from `start` (s = 0): up to v_target,
// cruising, down to min(v_end, v_target) at the end with acceleration 0,
// the highest peak that fits. A block too short to reach its end speed
// ends lower. May overrun only when allow_overrun (a successor to brake
// on); otherwise a stop that does not fit shortens the ramps. rt
BlockPlanKind plan_block(JerkPlan& plan, const Kinematics& start, double length_mm, double v_target_mm_s,
                         double v_end_mm_s, const JerkLimits& l, bool allow_overrun) noexcept;

// Distance of the fastest change from (v0, a0) to v1 with acceleration 0. rt
double change_distance(double v0_mm_s, double a0_mm_s2, double v1_mm_s, const JerkLimits& l) noexcept;

// An acceleration under way that the slope's ramp could not take back to 0
// before the speed passes 0 (braking) or v_max (speeding up): every plan
// from this state reverses, runs too fast, or takes the acceleration back
// faster than the slope allows. rt
bool ramp_outruns(const Kinematics& k, const JerkLimits& l, double v_max_mm_s) noexcept;

// The highest speed (acceleration 0) at the start of a block of length_mm
// from which it can still slow down to v_exit at its end. rt
double jerk_entry_velocity(double length_mm, double v_exit_mm_s, const JerkLimits& l) noexcept;

// The highest speed (acceleration 0) from which the path stops within
// length_mm (jerk_entry_velocity with v_exit 0). rt
inline double jerk_brake_velocity(double length_mm, const JerkLimits& l) noexcept {
  return jerk_entry_velocity(length_mm, 0.0, l);
}

// Rest-to-rest duration over length_mm at cruise speed v (closed form,
// for tests and estimates); +infinity when the limits are not valid. rt
double jerk_duration_estimate(double length_mm, double v_cmd_mm_s, const JerkLimits& l) noexcept;

}  // namespace nck::motion
