// Seeded property tests of the spindle interpolator: whatever the gear data,
// curve, tool limits, override and command sequence, the set point never
// exceeds its speed and acceleration limits (under slope_type TRAPEZ / SIN2
// its jerk limit a/tr or (pi/2) a/tr too), never becomes NaN, and every
// M19 ends exactly on its target, approached in the requested direction.
// Count from NCK_PROPERTY_COUNT (default 300).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>

#include "nck/spindle/accel_curve.hpp"
#include "spindle_test_util.hpp"

namespace nck::spindle {
namespace {

constexpr double kDt = 0.001;

int property_count() {
  const char* env = std::getenv("NCK_PROPERTY_COUNT");
  const int n = env ? std::atoi(env) : 0;
  return n > 0 ? n : 300;
}

struct Case {
  config::AxisConfig ax = test::spindle_axis_config();
  ToolDynamics tool{};
  double weight = 1.0;  // G130
};

Case random_case(std::mt19937& rng) {
  auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  Case c;
  auto& g = c.ax.gears[0];
  g.accel_mm_s2 = uni(1000, 6000);
  g.decel_mm_s2 = uni(1000, 6000);
  g.a_max = uni(2000, 8000);
  g.max_speed_mm_s = uni(600, 18000);
  g.rapid_mm_s = uni(300, 1200);
  g.position_gain_1_s = uni(1, 50);
  g.reference_pos = uni(0, 360);
  if (rng() % 2) { g.modulo_lower = -180; g.modulo_upper = 180; g.reference_pos -= 180; }
  switch (rng() % 4) {
    case 1:  // the seed's hyperbola, scaled in speed
    case 2: {  // the seed's polynomial (monotonic), scaled in speed
      const double k = uni(0.3, 1.5);
      g.curve.type = (rng() % 2) ? 1u : 2u;
      g.curve.limit_speed_deg_s = 12000 * k;
      g.curve.const_accel_deg_s2 = 16000;
      g.curve.a_min_deg_s2 = uni(500, 3000);
      if (g.curve.type == 1) { g.curve.b1 = 22857.142857; g.curve.b2 = 0.41666667; g.curve.b3 = 0.028571429; }
      else { g.curve.b1 = -0.88888888 / k; g.curve.b2 = 2.08333333E-5 / (k * k); g.curve.b3 = -1.92901234E-10 / (k * k * k); }
      break;
    }
    case 3:
      g.curve.type = 3;
      g.curve.a_max_deg_s2 = uni(2000, 16000);
      g.curve.a_min_deg_s2 = uni(300, 1500);
      g.curve.n1_deg_s = uni(500, 5000);
      g.curve.n2_deg_s = g.curve.n1_deg_s * uni(1, 3);
      break;
    default: break;
  }
  if (rng() % 2) c.tool = ToolDynamics{0, uni(100, 3000), uni(500, 5000)};
  c.weight = uni(0.5, 1.5);
  // slope_type (drawn last, so the cases above stay those of before): a
  // jerk-limited stage has no curve (the config layer makes it STEP).
  if (g.curve.type == 0 && rng() % 3 != 0) {
    g.slope_type = (rng() % 2) ? SlopeProfile::trapez : SlopeProfile::sin2;
    g.tr_acc_up_s = uni(0.005, 0.2);
    g.tr_acc_down_s = uni(0.005, 0.2);
    g.tr_dec_up_s = uni(0.005, 0.2);
    g.tr_dec_down_s = uni(0.005, 0.2);
  }
  return c;
}

// The limits the interpolator must keep, from the configuration alone.
double accel_bound(const Case& c, double speed_deg_s) {
  const auto& g = c.ax.gears[0];
  auto lim = [&](double a) {
    a = std::min(a * c.weight, g.a_max);
    if (c.tool.a_max_deg_s2 > 0) a = std::min(a, c.tool.a_max_deg_s2);
    return a;
  };
  return std::max(lim(curve_accel_deg_s2(g.curve, speed_deg_s, g.accel_mm_s2)),
                  lim(curve_accel_deg_s2(g.curve, speed_deg_s, g.decel_mm_s2)));
}

// Under TRAPEZ / SIN2 the steepest ramp: a/tr, sin^2 (pi/2) a/tr; 0 for STEP.
double jerk_bound(const Case& c) {
  const auto& g = c.ax.gears[0];
  if (!jerk_limited(g.slope_type)) return 0;
  auto lim = [&](double a) {
    a = std::min(a * c.weight, g.a_max);
    if (c.tool.a_max_deg_s2 > 0) a = std::min(a, c.tool.a_max_deg_s2);
    return a;
  };
  const double shape = g.slope_type == SlopeProfile::sin2 ? std::numbers::pi / 2 : 1.0;
  return shape * std::max({lim(g.accel_mm_s2) / g.tr_acc_up_s, lim(g.accel_mm_s2) / g.tr_acc_down_s,
                           lim(g.decel_mm_s2) / g.tr_dec_up_s, lim(g.decel_mm_s2) / g.tr_dec_down_s});
}

double speed_bound(const Case& c) {
  double v = c.ax.gears[0].max_speed_mm_s;
  if (c.tool.vb_max_rpm > 0) v = std::min(v, rpm_to_deg_s(c.tool.vb_max_rpm));
  return v;
}

class Checker {
 public:
  explicit Checker(const Case& c) : c_(c) {}
  // One cycle: tick and check the invariants. Returns false on a violation.
  bool step(SpindleAxis& s) {
    const double v_old = rpm_to_deg_s(s.status().set_rpm);
    s.tick(kDt);
    const auto& st = s.status();
    const double v = rpm_to_deg_s(st.set_rpm);
    EXPECT_TRUE(std::isfinite(v) && std::isfinite(st.set_pos_deg) && std::isfinite(st.act_rpm) &&
                std::isfinite(st.act_pos_deg) && std::isfinite(st.drive_output));
    EXPECT_LE(std::fabs(v), speed_bound(c_) * (1 + 1e-9));
    const double a = std::fabs(v - v_old) / kDt;
    const double bound = accel_bound(c_, std::fabs(v_old)) * (1 + 1e-9) + 1e-6;
    EXPECT_LE(a, bound) << "at speed " << v_old;
    if (const double j_max = jerk_bound(c_); j_max > 0) {
      const double j = std::fabs(v - 2 * v_old + v_older_) / (kDt * kDt);
      EXPECT_LE(j, j_max * (1 + 1e-6) + 1e-3) << "at speed " << v_old;
    }
    v_older_ = v_old;
    return !::testing::Test::HasFailure();
  }

 private:
  const Case& c_;
  double v_older_ = 0;  // the set speed two cycles back (the spindle starts at rest)
};

// Runs an M19 and checks it lands exactly, in the requested direction, with
// no overshoot (the distance to go only shrinks and never changes sign).
void check_m19(SpindleAxis& s, Checker& chk, double target, Direction dir, double rpm, std::mt19937& rng) {
  ASSERT_TRUE(s.position(target, dir, rpm).ok());
  double last_dist = 0;
  int planned_sign = 0;
  int i = 0;
  for (; i < 400000 && !s.status().in_position; ++i) {
    if (rng() % 5000 == 0) s.set_override_pct(std::uniform_real_distribution<double>(30, 150)(rng));
    ASSERT_TRUE(chk.step(s)) << "cycle " << i;
    const auto& st = s.status();
    if (st.mode != SpindleMode::position || st.distance_to_go_deg == 0) continue;
    const int sg = st.distance_to_go_deg > 0 ? 1 : -1;
    if (planned_sign == 0) {
      planned_sign = sg;
      if (dir != Direction::none) {
        ASSERT_EQ(sg, static_cast<int>(dir)) << "wrong direction";
      }
    } else {
      ASSERT_EQ(sg, planned_sign) << "overshoot";
      ASSERT_LE(std::fabs(st.distance_to_go_deg), std::fabs(last_dist) + 1e-9);
    }
    ASSERT_FALSE(st.set_rpm * planned_sign < 0) << "moved against the positioning direction";
    last_dist = st.distance_to_go_deg;
  }
  ASSERT_TRUE(s.status().in_position) << "never arrived";
  const auto& g = s.config().gears[0];
  EXPECT_NEAR(s.status().set_pos_deg, g.wrap(target), 1e-7);
}

TEST(SpindleProperty, LimitsTargetsAndNoNaN) {
  const int n = property_count();
  for (int k = 0; k < n; ++k) {
    std::mt19937 rng(static_cast<unsigned>(1000 + k));
    auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
    const Case c = random_case(rng);
    SCOPED_TRACE(::testing::Message() << "case " << k << ", slope_type " << slope_name(c.ax.gears[0].slope_type));
    auto s = test::make_spindle(c.ax, kDt);
    s.set_tool_dynamics(c.tool);
    ASSERT_TRUE(s.set_accel_weight_pct(c.weight * 100).ok());
    if (rng() % 2) s.feedforward_on();
    Checker chk(c);
    // Endless rotation with speed changes, reversals, override and feedhold.
    for (int phase = 0; phase < 3; ++phase) {
      s.set_override_pct(uni(30, 150));
      s.rotate(uni(-3000, 3000));
      const int ticks = static_cast<int>(uni(10, 3000));
      for (int i = 0; i < ticks; ++i) {
        if (i == ticks / 2 && rng() % 4 == 0) s.set_feedhold(true);
        ASSERT_TRUE(chk.step(s));
      }
      s.set_feedhold(false);
    }
    // M19 from rotation (homes first) and then from standstill.
    const Direction dirs[3] = {Direction::none, Direction::positive, Direction::negative};
    check_m19(s, chk, uni(-720, 720), dirs[rng() % 3], uni(50, 500), rng);
    check_m19(s, chk, uni(-720, 720), dirs[rng() % 3], uni(50, 500), rng);
    if (::testing::Test::HasFailure()) return;
  }
}

}  // namespace
}  // namespace nck::spindle
