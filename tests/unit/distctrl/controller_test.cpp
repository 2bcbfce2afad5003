// PID, limiter and the distance-control state machine, against values
// worked out by hand here.
#include "nck/distctrl/controller.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace nck::distctrl {
namespace {

constexpr double kDt = 0.001;

TEST(Pid, ProportionalIntegralDerivative) {
  Pid p;
  p.setup(0.5, 0, 0, kDt);
  p.reset();
  EXPECT_DOUBLE_EQ(p.step(2.0), 1.0);
  // I: constant error 1, Tn = 0.5 s: the I share equals the P share after 0.5 s.
  p.setup(1.0, 0.5, 0, kDt);
  p.reset();
  double u = 0;
  for (int k = 1; k <= 500; ++k) u = p.step(1.0);
  EXPECT_NEAR(u, 2.0, 1e-9);
  // D: error rising 1 mm/s, Tv = 0.01 s adds 0.01 mm.
  p.setup(1.0, 0, 0.01, kDt);
  p.reset();
  EXPECT_DOUBLE_EQ(p.step(0.0), 0.0);  // no derivative on the first sample
  EXPECT_NEAR(p.step(0.001), 0.001 + 0.01, 1e-12);
}

LimiterSettings limits() {
  LimiterSettings s;
  s.v_max_mm_s = 5;
  s.a_max_mm_s2 = 100;
  return s;
}

TEST(Limiter, AcceleratesAtAMaxUpToVMax) {
  Limiter l;
  l.setup(limits(), kDt);
  l.reset(0);
  double v_peak = 0;
  for (int k = 1; k <= 60; ++k) {
    l.step(10.0, 1.0);
    EXPECT_NEAR(l.v(), std::min(100.0 * k * kDt, 5.0), 1e-9) << k;
    v_peak = std::max(v_peak, l.v());
  }
  EXPECT_DOUBLE_EQ(v_peak, 5.0);
}

TEST(Limiter, ReachesTheTargetWithoutOvershoot) {
  Limiter l;
  l.setup(limits(), kDt);
  l.reset(0);
  double top = 0;
  for (int k = 0; k < 2000; ++k) top = std::max(top, l.step(1.0, 1.0));
  EXPECT_NEAR(l.pos(), 1.0, 1e-9);
  EXPECT_LE(top, 1.0 + 1e-6);
  EXPECT_NEAR(l.v(), 0.0, 1e-9);
}

TEST(Limiter, WeightsSlowTheMoveTowardsTheWorkpiece) {
  LimiterSettings s = limits();
  s.v_weight_down = 0.5;  // list value 500 (0.1 %)
  s.a_weight_down = 0.25;
  Limiter l;
  l.setup(s, kDt);
  l.reset(0);
  l.step(-10.0, 1.0);
  EXPECT_NEAR(l.v(), -25.0 * kDt, 1e-12);  // a = 100 * 0.25
  for (int k = 0; k < 1000; ++k) l.step(-10.0, 1.0);
  EXPECT_NEAR(l.v(), -2.5, 1e-9);  // v = 5 * 0.5
  l.reset(0);
  l.step(10.0, 1.0);  // lifting: unweighted
  EXPECT_NEAR(l.v(), 100.0 * kDt, 1e-12);
}

TEST(Limiter, AdaptiveAccelerationIsLinearInTheError) {
  LimiterSettings s = limits();
  s.adaptive = true;
  s.a_min_mm_s2 = 20;
  s.a_max_mm_s2 = 100;
  s.err_a_min_mm = 0.1;
  s.err_a_max_mm = 0.5;
  Limiter l;
  l.setup(s, kDt);
  EXPECT_DOUBLE_EQ(l.accel_for(0.05), 20);
  EXPECT_DOUBLE_EQ(l.accel_for(-0.1), 20);
  EXPECT_NEAR(l.accel_for(0.3), 60, 1e-12);
  EXPECT_DOUBLE_EQ(l.accel_for(0.9), 100);
  l.reset(0);
  l.step(10.0, 0.2);  // a = 20 + 0.25 * 80 = 40
  EXPECT_NEAR(l.v(), 40 * kDt, 1e-12);
}

Settings settings() {
  Settings s;
  s.filter.kind = FilterKind::moving_average;
  s.filter.n_cycles = 1;
  s.limiter.v_max_mm_s = 50;
  s.limiter.a_max_mm_s2 = 5000;
  s.max_deviation_mm = 5;
  s.min_pos_mm = 0;
  s.max_pos_mm = 10;
  s.max_act_value_change_mm_s = 0;
  return s;
}

Switch on_surface(double set_pos) {
  Switch w;
  w.op = Op::on;
  w.set_pos_mm = set_pos;
  return w;
}

// A tool at programmed height z_prog above a surface at z_surf: the sensor
// reads the gap z_prog + offset - z_surf.
double run(Controller& c, double z_prog, double z_surf, int cycles) {
  for (int k = 0; k < cycles; ++k) {
    EXPECT_EQ(c.step({true, z_prog + c.offset_mm() - z_surf}, z_prog), ErrorId{});
  }
  return c.offset_mm();
}

TEST(Controller, SurfaceModeFollowsTheSurface) {
  Controller c;
  c.setup(settings(), kDt);
  ASSERT_EQ(c.apply(on_surface(0.0)), ErrorId{});
  EXPECT_EQ(c.state(), State::active);
  // Programmed 2 mm above SET_POS 0; the real surface is 0.7 mm higher.
  EXPECT_NEAR(run(c, 2.0, 0.7, 500), 0.7, 1e-6);
  EXPECT_NEAR(c.dist_error_mm(), 0.0, 1e-6);
}

TEST(Controller, ConstDistKeepsTheSetDistance) {
  Controller c;
  c.setup(settings(), kDt);
  Switch w;
  w.op = Op::on;
  w.const_dist = true;
  w.set_dist_mm = 1.5;
  ASSERT_EQ(c.apply(w), ErrorId{});
  EXPECT_EQ(c.state(), State::active_const);
  // gap = 5 + offset - 0.2 must become 1.5: offset = -3.3
  EXPECT_NEAR(run(c, 5.0, 0.2, 1000), -3.3, 1e-6);
}

TEST(Controller, TransitionsAndTheirErrors) {
  Controller c;
  c.setup(settings(), kDt);
  Switch on;
  on.op = Op::on;
  EXPECT_EQ(c.apply(on), ErrorId::NcDistCtrlNoSetPos);  // 310024
  EXPECT_EQ(c.state(), State::inactive);
  ASSERT_EQ(c.apply(on_surface(0)), ErrorId{});
  Switch cst = on;
  cst.const_dist = true;
  cst.set_dist_mm = 1;
  EXPECT_EQ(c.apply(cst), ErrorId::NcDistCtrlModeChange);  // 310025
  EXPECT_EQ(c.state(), State::active);
  Switch fr;
  fr.op = Op::freeze;
  c.apply(fr);
  EXPECT_EQ(c.state(), State::freeze);
  EXPECT_EQ(c.apply(cst), ErrorId{});  // through FREEZE the mode may change
  EXPECT_EQ(c.state(), State::active_const);
  Switch off;
  off.op = Op::off;
  run(c, 3.0, 0.0, 200);  // offset -2: gap 1
  EXPECT_NEAR(c.offset_mm(), -2.0, 1e-6);
  c.apply(off);
  EXPECT_EQ(c.state(), State::turning_off);
  int k = 0;
  while (c.state() == State::turning_off && k++ < 5000) c.step({true, 1.0}, 3.0);
  EXPECT_EQ(c.state(), State::inactive);
  EXPECT_DOUBLE_EQ(c.offset_mm(), 0.0);
  // v_max 50 mm/s, a 5000 mm/s^2: 2 mm take 2/50 + 50/5000 = 0.05 s
  EXPECT_NEAR(k * kDt, 0.05, 0.003);
}

TEST(Controller, FreezeHoldsAndNoMoveKeepsTheOffset) {
  Controller c;
  c.setup(settings(), kDt);
  c.apply(on_surface(0));
  run(c, 2.0, 0.5, 300);
  Switch fr;
  fr.op = Op::freeze;
  c.apply(fr);
  for (int k = 0; k < 100; ++k) c.step({true, 9.0}, 2.0);  // a hole: the sensor sees far
  EXPECT_NEAR(c.offset_mm(), 0.5, 1e-6);
  Switch off;
  off.op = Op::off;
  off.no_move = true;
  c.apply(off);
  EXPECT_EQ(c.state(), State::inactive);
  EXPECT_NEAR(c.offset_mm(), 0.5, 1e-6);
}

TEST(Controller, SwitchingKeepsTheOffsetVelocity) {
  Controller c;
  c.setup(settings(), kDt);
  c.apply(on_surface(0));
  c.step({true, 2.0 - 1.0}, 2.0);  // 1 mm error: the offset starts moving
  c.step({true, 2.0 + c.offset_mm() - 1.0}, 2.0);
  const double v = c.offset_v_mm_s();
  ASSERT_GT(v, 0);
  Switch fr;
  fr.op = Op::freeze;
  c.apply(fr);
  EXPECT_DOUBLE_EQ(c.offset_v_mm_s(), v);  // it brakes from there within a_max
  c.step({true, 2.0}, 2.0);
  EXPECT_NEAR(c.offset_v_mm_s(), std::max(0.0, v - 5000 * kDt), 1e-9);
}

TEST(Controller, DropoutHoldsTheOffset) {
  Controller c;
  c.setup(settings(), kDt);
  c.apply(on_surface(0));
  run(c, 2.0, 0.5, 300);
  for (int k = 0; k < 50; ++k) EXPECT_EQ(c.step({false, 0.0}, 2.0), ErrorId{});
  EXPECT_NEAR(c.offset_mm(), 0.5, 1e-6);
  // Meanwhile the sheet rose 0.3 mm: the filter restarts, no rate error.
  Settings s = settings();
  s.max_act_value_change_mm_s = 100;  // 0.1 mm per cycle
  Controller d;
  d.setup(s, kDt);
  d.apply(on_surface(0));
  run(d, 2.0, 0.5, 300);
  for (int k = 0; k < 50; ++k) d.step({false, 0.0}, 2.0);
  EXPECT_EQ(d.step({true, 2.0 + d.offset_mm() - 0.8}, 2.0), ErrorId{});
  EXPECT_NEAR(run(d, 2.0, 0.8, 300), 0.8, 1e-6);
}

TEST(Controller, SensorRangeWithTolerance) {
  Settings s = settings();
  s.tolerance_mm = 0.5;  // valid 0.5 .. 9.5
  for (auto [value, id] : {std::pair{9.6, ErrorId::DistCtrlSensorAbove}, std::pair{0.4, ErrorId::DistCtrlSensorBelow}}) {
    Controller c;
    c.setup(s, kDt);
    c.apply(on_surface(0));
    EXPECT_EQ(c.step({true, 9.4}, 9.4), ErrorId{});
    EXPECT_EQ(c.step({true, value}, 9.4), id);
    EXPECT_EQ(c.state(), State::error);
  }
  EXPECT_EQ(number(ErrorId::DistCtrlSensorAbove), 310019u);
  EXPECT_EQ(number(ErrorId::DistCtrlSensorBelow), 310020u);
}

TEST(Controller, RateMonitorAndMaxDeviation) {
  Settings s = settings();
  s.max_act_value_change_mm_s = 100;  // 0.1 mm per 1 ms cycle
  Controller c;
  c.setup(s, kDt);
  c.apply(on_surface(0));
  EXPECT_EQ(c.step({true, 2.0}, 2.0), ErrorId{});
  EXPECT_EQ(c.step({true, 2.09}, 2.0), ErrorId{});
  EXPECT_EQ(c.step({true, 2.2}, 2.0), ErrorId::DistCtrlSensorRate);
  s = settings();
  s.max_deviation_mm = 0.3;
  Controller d;
  d.setup(s, kDt);
  d.apply(on_surface(0));
  ErrorId e{};
  for (int k = 0; k < 1000 && e == ErrorId{}; ++k) e = d.step({true, 2.0 + d.offset_mm() - 1.0}, 2.0);
  EXPECT_EQ(e, ErrorId::DistCtrlMaxDeviation);
  EXPECT_DOUBLE_EQ(d.offset_mm(), 0.3);
}

TEST(Controller, RefOffsetShiftsTheSensorRange) {
  Settings s = settings();
  s.ref_offset_mm = 1.0;  // the sensor reads 1 mm more than the gap
  Controller c;
  c.setup(s, kDt);
  c.apply(on_surface(0));
  for (int k = 0; k < 500; ++k) c.step({true, 1.0 + 2.0 + c.offset_mm() - 0.4}, 2.0);
  EXPECT_NEAR(c.offset_mm(), 0.4, 1e-6);
}

TEST(Controller, OverridesReplaceTheListValues) {
  Controller c;
  c.setup(settings(), kDt);
  Switch w = on_surface(0);
  w.kp = 0.5;
  c.apply(w);
  c.step({true, 2.0 - 1.0}, 2.0);  // error 1 mm: target 0.5, limited by a*dt^2 in the first cycle
  EXPECT_EQ(c.settings().kp, 0.5);
  c.stop(true);
  EXPECT_EQ(c.settings().kp, 1.0);
  EXPECT_EQ(c.state(), State::inactive);
}

}  // namespace
}  // namespace nck::distctrl
