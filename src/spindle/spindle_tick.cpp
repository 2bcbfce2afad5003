// The cyclic part of the spindle interpolator: speed ramps, exact
// positioning, homing on the zero mark, the control limit.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "nck/spindle/spindle_axis.hpp"

namespace nck::spindle {
namespace {
int sign_of(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
}  // namespace

bool SpindleAxis::tick(double dt, bool refresh_status) noexcept {
  if (!configured_ || !(dt > 0) || !std::isfinite(dt)) return false;
  if (at_rest()) {  // a stopped spindle whose drive has settled: nothing changes
    set_.step_deg = 0;
    return false;
  }
  if (cruise_epoch_ == epoch_) cruise(dt);
  else if (tick_all(dt)) cruise_epoch_ = epoch_;
  if (refresh_status) update_status();  // with the last feedback, until the drive's answer comes
  return true;
}

// A tick that may change anything; true when it found the spindle turning
// at its commanded speed with a linear slope (the next ticks may cruise).
bool SpindleAxis::tick_all(double dt) noexcept {
  ++epoch_;
  const double v_old = set_.vel_deg_s;
  set_.step_deg = 0;
  jerk_.used = false;
  bool at_speed = false;
  switch (mode_) {
    case SpindleMode::stop:
    case SpindleMode::error: ramp_to(0, dt); break;
    case SpindleMode::rotate: at_speed = tick_rotate(dt); break;
    case SpindleMode::position:
    case SpindleMode::gear_change: tick_position(dt); break;
    case SpindleMode::homing: tick_homing(dt); break;
    case SpindleMode::axis:
      set_.vel_deg_s = axis_.vel_deg_s;
      set_.step_deg = axis_.step_deg;
      axis_.step_deg = 0;
      break;
  }
  if (!jerk_.used) {  // something else moved the set point: a later ramp plans anew from a = 0
    jerk_.kind = JerkRamp::Kind::none;
    jerk_.a_deg_s2 = 0;
  }
  set_.accel_deg_s2 = (set_.vel_deg_s - v_old) / dt;
  return at_speed;
}

// What tick_all does to a spindle at its commanded speed when no command
// came since: advance by a cycle at that speed. The rest of it (the control
// limit, the jerk ramp's reset, an acceleration of 0) was done by the tick
// that found it at speed and gives the same again.
void SpindleAxis::cruise(double dt) noexcept {
  assert(mode_ == SpindleMode::rotate && !speed_.feedhold && !jerk_limited_slope() && set_.vel_deg_s != 0 &&
         set_.vel_deg_s == rotation_speed_deg_s() && set_.accel_deg_s2 == 0 &&
         jerk_.kind == JerkRamp::Kind::none && !jerk_.used);
  set_.step_deg = 0;
  advance(set_.vel_deg_s * dt);
}

// Stopped, standing, the drive measured exactly no speed and no following
// error (a simulated drive cuts its decay to zero once settled): a whole
// tick would compute the same state again (most spindles, most of the time).
bool SpindleAxis::at_rest() const noexcept {
  return mode_ == SpindleMode::stop && set_.vel_deg_s == 0 && set_.accel_deg_s2 == 0 &&
         status_.act_rpm == 0 && status_.lag_deg == 0;
}

void SpindleAxis::advance(double step_deg) noexcept {
  set_.pos_deg = gear().wrap(set_.pos_deg + step_deg);
  set_.step_deg += step_deg;
}

// True when the spindle was at the target speed already (and not jerk-limited).
bool SpindleAxis::ramp_to(double target, double dt) noexcept {
  if (jerk_limited_slope()) {
    jerk_ramp_to(target, dt);
    return false;
  }
  const double v = set_.vel_deg_s;
  // Reversing goes through standstill: brake to 0 first.
  const double goal = (v != 0 && sign_of(target) == -sign_of(v)) ? 0.0 : target;
  const double diff = goal - v;
  if (diff == 0 && v != 0) {  // at speed: no acceleration to look up
    advance(v * dt);
    return true;
  }
  const bool faster = std::fabs(goal) > std::fabs(v);
  const double a = faster ? accel_up(v) : accel_down(v);
  const double dv = std::min(std::fabs(diff), a * dt);
  set_.vel_deg_s = v + std::copysign(dv, diff);
  advance(set_.vel_deg_s * dt);
  return false;
}

bool SpindleAxis::tick_rotate(double dt) noexcept {
  const bool at_speed = ramp_to(speed_.feedhold ? 0.0 : rotation_speed_deg_s(), dt);
  // Above the control limit the encoder signal is not valid: the loop opens
  // and the reference is lost (FCT-S1 2.4.2).
  const double limit = gear().control_limit_deg_s;
  if (!cfg_.open_loop && limit > 0 && std::fabs(set_.vel_deg_s) > limit) {
    ref_.lost = true;
    ref_.homed = false;
  }
  return at_speed;
}

double SpindleAxis::positioning_speed_deg_s() const noexcept {
  const double f = pos_.overridable ? override_factor() : 1.0;
  return speed_.feedhold ? 0.0 : std::fabs(limit_speed(pos_.speed_deg_s * f));
}

void SpindleAxis::tick_position(double dt) noexcept {
  if (pos_.done) {
    set_.vel_deg_s = 0;
    return;
  }
  if (mode_ == SpindleMode::gear_change && !cfg_.can_position) {
    ramp_to(0, dt);  // nothing to position: standstill is the change position
    if (set_.vel_deg_s == 0) pos_.done = true;
    return;
  }
  if (!pos_.planned) {
    const int req = static_cast<int>(pos_.requested_dir);
    if (req != 0 && set_.vel_deg_s * req < 0) {  // turning the wrong way: stop first
      ramp_to(0, dt);
      return;
    }
    if (jerk_limited_slope() && jerk_finish_speed_ramp(dt)) return;
    plan_positioning(dt);
    if (pos_.done) return;
  }
  if (jerk_limited_slope()) jerk_step_positioning(dt);
  else step_positioning(dt);
}

void SpindleAxis::plan_positioning(double dt) noexcept {
  const double travel = m19_travel_deg(set_.pos_deg, pos_.target_deg, pos_.requested_dir, set_.vel_deg_s,
                                       gear().modulo_low_deg, gear().modulo_high_deg);
  int d = sign_of(travel);
  if (d == 0) d = static_cast<int>(pos_.requested_dir);
  if (d == 0) d = sign_of(set_.vel_deg_s);
  const double u = std::fabs(set_.vel_deg_s);
  pos_.planned = true;
  if (d == 0) {  // standing on the target already
    pos_.done = true;
    pos_.remaining_deg = 0;
    return;
  }
  pos_.dir = d;
  double stop = 0;
  if (jerk_limited_slope()) {
    jerk_.kind = JerkRamp::Kind::none;  // the next step plans this positioning
    stop = jerk_stop_distance_deg(u, d);
  } else {
    pos_.speed_cap_deg_s = std::max(u, positioning_speed_deg_s());
    pos_.brake_accel_deg_s2 = min_accel_down(pos_.speed_cap_deg_s);
    const double a = pos_.brake_accel_deg_s2;
    stop = u * (u + a * dt) / (2 * a);
  }
  // Too close to stop in time: go round once more (or several times).
  double s = std::fabs(travel);
  const double range = gear().range_deg();
  if (s < stop) s += std::ceil((stop - s) / range) * range;
  pos_.remaining_deg = s;
}

void SpindleAxis::step_positioning(double dt) noexcept {
  const double s = pos_.remaining_deg;
  const double u = std::max(0.0, set_.vel_deg_s * pos_.dir);
  if (s <= 0) {  // arrived in the last cycle; the set speed returns to 0
    set_.vel_deg_s = 0;
    pos_.done = true;
    return;
  }
  const double a = pos_.brake_accel_deg_s2;
  const double vmax = std::min(positioning_speed_deg_s(), pos_.speed_cap_deg_s);
  const double up = u < vmax ? std::min(u + accel_up(u) * dt, vmax) : std::max(u - a * dt, vmax);
  // Highest speed from which braking with a, one cycle at a time, ends
  // exactly on the target: s = v (v + a dt) / (2 a).
  const double brake = a * dt * (std::sqrt(0.25 + 2 * s / (a * dt * dt)) - 0.5);
  const double nu = std::max({std::min(up, brake), u - a * dt, 0.0});
  set_.vel_deg_s = pos_.dir * nu;
  if (nu * dt >= s) {  // the last step lands on the target, never beyond
    advance(pos_.dir * s);
    pos_.remaining_deg = 0;
  } else {
    advance(pos_.dir * nu * dt);
    pos_.remaining_deg = s - nu * dt;
  }
}

double SpindleAxis::homing_speed_deg_s() const noexcept {
  const double rapid = gear().rapid_speed_deg_s;
  double v = std::min(rapid > 0 ? rapid : 1.0, max_speed_deg_s());
  const double limit = gear().control_limit_deg_s;
  if (limit > 0) v = std::min(v, limit);  // the encoder must be valid
  return v;
}

bool SpindleAxis::crossed_mark(double from_deg, double step_deg) const noexcept {
  if (step_deg == 0) return false;
  const double mark = gear().wrap(gear().reference_pos_deg);
  const double r = gear().range_deg();
  const double ahead = step_deg > 0 ? wrap_modulo(mark - from_deg, 0, r) : wrap_modulo(from_deg - mark, 0, r);
  return ahead <= std::fabs(step_deg);
}

void SpindleAxis::tick_homing(double dt) noexcept {
  if (cfg_.drive_homing) {  // the drive homes once the set point stands (drive_homed)
    ramp_to(0, dt);
    return;
  }
  if (homing_.mark_found) {  // reference set: position onto the reference position
    tick_position(dt);
    if (pos_.done) {
      mode_ = SpindleMode::stop;
      pos_.done = pos_.planned = false;
    }
    return;
  }
  const double from = set_.pos_deg;
  const double v_old = std::fabs(set_.vel_deg_s);
  ramp_to(speed_.feedhold ? 0.0 : homing_.dir * homing_speed_deg_s(), dt);
  const double limit = gear().control_limit_deg_s;
  const bool encoder_valid = limit <= 0 || std::max(v_old, std::fabs(set_.vel_deg_s)) <= limit;
  if (encoder_valid && set_.step_deg * homing_.dir > 0 && crossed_mark(from, set_.step_deg)) on_reference();
}

void SpindleAxis::drive_homed(double drive_pos_deg) noexcept {
  if (mode_ != SpindleMode::homing) return;
  const Changed changed(*this);
  set_.pos_deg = gear().wrap(drive_sense() * drive_pos_deg);
  ref_.homed = true;
  ref_.lost = false;
  mode_ = SpindleMode::stop;
  homing_.after = AfterHoming::none;
  update_status();
}

void SpindleAxis::on_reference() noexcept {
  // The simulated zero mark sits at the reference position, so the set
  // position needs no jump; the reference is simply known from now on.
  ref_.homed = true;
  ref_.lost = false;
  homing_.mark_found = true;
  switch (homing_.after) {
    case AfterHoming::go_to_target:
      begin_positioning(SpindleMode::position, homing_.target_deg, homing_.target_dir,
                        homing_.target_speed_deg_s, homing_.target_overridable);
      break;
    case AfterHoming::stop: mode_ = SpindleMode::stop; break;
    case AfterHoming::go_to_reference:
    case AfterHoming::none:
      begin_positioning(SpindleMode::homing, gear().reference_pos_deg, static_cast<Direction>(homing_.dir),
                        homing_speed_deg_s(), false);
      break;
  }
  homing_.after = AfterHoming::none;
}

}  // namespace nck::spindle
