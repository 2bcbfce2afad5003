// The cyclic part of the spindle interpolator: speed ramps, exact
// positioning, homing on the zero mark, the control limit.
#include <algorithm>
#include <cmath>

#include "nck/spindle/spindle_axis.hpp"

namespace nck::spindle {
namespace {
int sign_of(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }
}  // namespace

void SpindleAxis::tick(double dt) noexcept {
  if (!configured_ || !(dt > 0) || !std::isfinite(dt)) return;
  const double v_old = v_deg_s_;
  step_deg_ = 0;
  switch (mode_) {
    case SpindleMode::stop:
    case SpindleMode::error: ramp_to(0, dt); break;
    case SpindleMode::rotate: tick_rotate(dt); break;
    case SpindleMode::position:
    case SpindleMode::gear_change: tick_position(dt); break;
    case SpindleMode::homing: tick_homing(dt); break;
    case SpindleMode::axis:
      v_deg_s_ = axis_vel_deg_s_;
      step_deg_ = axis_step_deg_;
      axis_step_deg_ = 0;
      break;
  }
  a_deg_s2_ = (v_deg_s_ - v_old) / dt;
  drive_model(step_deg_, dt);
  update_status();
}

void SpindleAxis::advance(double step, double) noexcept {
  pos_deg_ = wrap_modulo(pos_deg_ + step, gear().modulou, gear().moduloo);
  step_deg_ += step;
}

void SpindleAxis::ramp_to(double target, double dt) noexcept {
  const double v = v_deg_s_;
  // Reversing goes through standstill: brake to 0 first.
  const double goal = (v != 0 && sign_of(target) == -sign_of(v)) ? 0.0 : target;
  const double diff = goal - v;
  const bool faster = std::fabs(goal) > std::fabs(v);
  const double a = faster ? accel_up(v) : accel_down(v);
  const double dv = std::min(std::fabs(diff), a * dt);
  v_deg_s_ = v + std::copysign(dv, diff);
  advance(v_deg_s_ * dt, dt);
}

void SpindleAxis::tick_rotate(double dt) noexcept {
  const double target = feedhold_ ? 0.0 : limit_speed(rpm_to_deg_s(programmed_rpm_) * override_factor());
  ramp_to(target, dt);
  // Above the control limit the encoder signal is not valid: the loop opens
  // and the reference is lost (FCT-S1 2.4.2).
  const double limit = gear().vb_regelgrenze;
  if (!p_.open_loop && limit > 0 && std::fabs(v_deg_s_) > limit) {
    ref_lost_ = true;
    homed_ = false;
  }
}

double SpindleAxis::positioning_speed_deg_s() const noexcept {
  const double f = pos_overridable_ ? override_factor() : 1.0;
  return feedhold_ ? 0.0 : std::fabs(limit_speed(pos_speed_deg_s_ * f));
}

void SpindleAxis::tick_position(double dt) noexcept {
  if (pos_done_) {
    v_deg_s_ = 0;
    return;
  }
  if (mode_ == SpindleMode::gear_change && !p_.can_position) {
    ramp_to(0, dt);  // nothing to position: standstill is the change position
    if (v_deg_s_ == 0) pos_done_ = true;
    return;
  }
  if (!planned_) {
    const int req = static_cast<int>(pos_dir_req_);
    if (req != 0 && v_deg_s_ * req < 0) {  // turning the wrong way: stop first
      ramp_to(0, dt);
      return;
    }
    plan_positioning(dt);
    if (pos_done_) return;
  }
  step_positioning(dt);
}

void SpindleAxis::plan_positioning(double dt) noexcept {
  const double travel = m19_travel_deg(pos_deg_, target_deg_, pos_dir_req_, v_deg_s_, gear().modulou,
                                       gear().moduloo);
  int d = sign_of(travel);
  if (d == 0) d = static_cast<int>(pos_dir_req_);
  if (d == 0) d = sign_of(v_deg_s_);
  const double u = std::fabs(v_deg_s_);
  planned_ = true;
  if (d == 0) {  // standing on the target already
    pos_done_ = true;
    remaining_deg_ = 0;
    return;
  }
  pos_dir_ = d;
  pos_speed_cap_ = std::max(u, positioning_speed_deg_s());
  pos_accel_ = min_accel_down(pos_speed_cap_);
  // Too close to stop in time: go round once more (or several times).
  double s = std::fabs(travel);
  const double a = pos_accel_;
  const double stop = u * (u + a * dt) / (2 * a);
  if (s < stop) s += std::ceil((stop - s) / range_deg()) * range_deg();
  remaining_deg_ = s;
}

void SpindleAxis::step_positioning(double dt) noexcept {
  const double s = remaining_deg_;
  const double u = std::max(0.0, v_deg_s_ * pos_dir_);
  if (s <= 0) {  // arrived in the last cycle; the set speed returns to 0
    v_deg_s_ = 0;
    pos_done_ = true;
    return;
  }
  const double a = pos_accel_;
  const double vmax = std::min(positioning_speed_deg_s(), pos_speed_cap_);
  const double up = u < vmax ? std::min(u + accel_up(u) * dt, vmax) : std::max(u - a * dt, vmax);
  // Highest speed from which braking with a, one cycle at a time, ends
  // exactly on the target: s = v (v + a dt) / (2 a).
  const double brake = a * dt * (std::sqrt(0.25 + 2 * s / (a * dt * dt)) - 0.5);
  const double nu = std::max({std::min(up, brake), u - a * dt, 0.0});
  v_deg_s_ = pos_dir_ * nu;
  if (nu * dt >= s) {  // the last step lands on the target, never beyond
    advance(pos_dir_ * s, dt);
    remaining_deg_ = 0;
  } else {
    advance(pos_dir_ * nu * dt, dt);
    remaining_deg_ = s - nu * dt;
  }
}

double SpindleAxis::homing_speed_deg_s() const noexcept {
  double v = std::min(gear().vb_eilgang > 0 ? gear().vb_eilgang : 1.0, max_speed_deg_s());
  if (gear().vb_regelgrenze > 0) v = std::min(v, gear().vb_regelgrenze);  // the encoder must be valid
  return v;
}

bool SpindleAxis::crossed_mark(double from_deg, double step_deg) const noexcept {
  if (step_deg == 0) return false;
  const double mark = wrap_modulo(gear().pos_refpkt, gear().modulou, gear().moduloo);
  const double r = range_deg();
  const double ahead = step_deg > 0 ? wrap_modulo(mark - from_deg, 0, r) : wrap_modulo(from_deg - mark, 0, r);
  return ahead <= std::fabs(step_deg);
}

void SpindleAxis::tick_homing(double dt) noexcept {
  if (mark_found_) {  // reference set: position onto pos_refpkt
    tick_position(dt);
    if (pos_done_) {
      mode_ = SpindleMode::stop;
      pos_done_ = planned_ = false;
    }
    return;
  }
  const double from = pos_deg_;
  const double v_old = std::fabs(v_deg_s_);
  ramp_to(feedhold_ ? 0.0 : home_dir_ * homing_speed_deg_s(), dt);
  const double limit = gear().vb_regelgrenze;
  const bool encoder_valid = limit <= 0 || std::max(v_old, std::fabs(v_deg_s_)) <= limit;
  if (encoder_valid && step_deg_ * home_dir_ > 0 && crossed_mark(from, step_deg_)) on_reference(dt);
}

void SpindleAxis::on_reference(double) noexcept {
  // The simulated zero mark sits at pos_refpkt, so the set position needs
  // no jump; the reference is simply known from now on.
  homed_ = true;
  ref_lost_ = false;
  mark_found_ = true;
  switch (after_home_) {
    case After::target:
      begin_positioning(SpindleMode::position, home_target_deg_, home_target_dir_, home_target_speed_,
                        home_target_overridable_);
      break;
    case After::stop: mode_ = SpindleMode::stop; break;
    case After::refpkt:
    case After::none:
      begin_positioning(SpindleMode::homing, gear().pos_refpkt, static_cast<Direction>(home_dir_),
                        homing_speed_deg_s(), false);
      break;
  }
  after_home_ = After::none;
}

}  // namespace nck::spindle
