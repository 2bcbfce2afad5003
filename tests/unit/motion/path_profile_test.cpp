// Trapezoidal path profile: exact end, limits, triangle, feedhold, override.
#include "nck/motion/path_profile.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace nck::motion {
namespace {

constexpr double kDt = 0.001;
constexpr double kRel = 1e-9;  // relative slack for rounding in the limit checks

struct Trace {
  std::vector<double> s;  // s after each step (s[0] = start)
  std::size_t steps = 0;
  bool finished = false;
};

// Steps at a constant override until finished (or max_steps) and checks every
// cycle: velocity within [0, v_max], acceleration within the limits, and the
// set point moving by v*dt (the last step of a blended segment may move less:
// the rest is carried into the next segment).
Trace run_checked(PathProfile& p, double ovr, std::size_t max_steps, double dt = kDt) {
  Trace r;
  r.s.push_back(p.s());
  const PathLimits& l = p.limits();
  double v_prev = p.v();
  for (std::size_t k = 0; k < max_steps && !p.finished(); ++k) {
    const ProfileSample smp = p.step(dt, ovr);
    const double v = smp.v_mm_s;
    const double fd = (smp.s_mm - r.s.back()) / dt;
    EXPECT_TRUE(std::isfinite(smp.s_mm) && std::isfinite(v));
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, l.v_max_mm_s * (1 + kRel) + 1e-9) << "step " << k;
    EXPECT_LE((v - v_prev) / dt, l.a_acc_mm_s2 * (1 + 1e-6) + 1e-6) << "step " << k;
    EXPECT_GE((v - v_prev) / dt, -l.a_dec_mm_s2 * (1 + 1e-6) - 1e-6) << "step " << k;
    if (smp.finished) {
      EXPECT_LE(fd, v * (1 + 1e-9) + 1e-9);
    } else {
      EXPECT_NEAR(fd, v, 1e-6 * std::max(1.0, v));
    }
    v_prev = v;
    r.s.push_back(smp.s_mm);
    ++r.steps;
    r.finished = smp.finished;
  }
  return r;
}

double max_speed(const Trace& r, double dt = kDt) {
  double m = 0.0;
  for (std::size_t i = 1; i < r.s.size(); ++i) m = std::max(m, (r.s[i] - r.s[i - 1]) / dt);
  return m;
}

TEST(DiscreteBrake, VelocityAndDistanceAreInverse) {
  const double a = 1234.5, dt = 0.002;
  for (double d : {1e-9, 1e-6, 0.003, 0.1, 1.0, 17.3, 250.0, 1e5}) {
    const double v = discrete_brake_velocity(d, a, dt);
    EXPECT_NEAR(discrete_brake_distance(v, a, dt), d, 1e-9 * std::max(1.0, d)) << d;
    // Close to the continuous sqrt(2ad) for long distances.
    if (d > 1.0) {
      EXPECT_NEAR(v, std::sqrt(2 * a * d), 0.01 * std::sqrt(2 * a * d)) << d;
    }
  }
  EXPECT_EQ(discrete_brake_velocity(0.0, a, dt), 0.0);
  EXPECT_EQ(discrete_brake_velocity(-1.0, a, dt), 0.0);
  EXPECT_EQ(discrete_brake_velocity(1.0, NAN, dt), 0.0);
  // One staircase step: d = a dt^2 is covered in exactly one cycle at a dt.
  EXPECT_NEAR(discrete_brake_velocity(a * dt * dt, a, dt), a * dt, 1e-12);
}

TEST(PathProfile, TrapezoidReachesEndExactly) {
  PathProfile p;
  const PathLimits l{100.0, 500.0, 1000.0};
  ASSERT_TRUE(p.start(100.0, 50.0, l));
  const Trace r = run_checked(p, 1.0, 100000);
  ASSERT_TRUE(r.finished);
  EXPECT_EQ(p.s(), 100.0);
  EXPECT_EQ(r.s.back(), 100.0);
  EXPECT_NEAR(max_speed(r), 50.0, 1e-9);  // cruises at F, not at v_max
  // Analytic: 50/500 + 50/1000 + (100 - 2.5 - 1.25)/50 = 2.075 s.
  EXPECT_NEAR(duration_estimate(100.0, 50.0, l), 2.075, 1e-12);
  EXPECT_NEAR(static_cast<double>(r.steps) * kDt, 2.075, 3 * kDt);
  // After the end: standstill at the end.
  const ProfileSample after = p.step(kDt, 1.0);
  EXPECT_TRUE(after.finished);
  EXPECT_EQ(after.s_mm, 100.0);
  EXPECT_EQ(after.v_mm_s, 0.0);
}

TEST(PathProfile, CruiseCappedByVmax) {
  PathProfile p;
  ASSERT_TRUE(p.start(100.0, 1000.0, PathLimits{40.0, 500.0, 500.0}));
  const Trace r = run_checked(p, 1.0, 100000);
  ASSERT_TRUE(r.finished);
  EXPECT_NEAR(max_speed(r), 40.0, 1e-9);
  // Override above 100 % does not pass v_max either.
  ASSERT_TRUE(p.start(100.0, 30.0, PathLimits{40.0, 500.0, 500.0}));
  EXPECT_NEAR(max_speed(run_checked(p, 1.5, 100000)), 40.0, 1e-9);
}

TEST(PathProfile, TriangleWhenTooShort) {
  // L = 1, a = 100 both: peak sqrt(L a) = 10 mm/s < v_cmd; time 2*sqrt(L/a) = 0.2 s.
  PathProfile p;
  const PathLimits l{1000.0, 100.0, 100.0};
  ASSERT_TRUE(p.start(1.0, 500.0, l));
  const Trace r = run_checked(p, 1.0, 100000);
  ASSERT_TRUE(r.finished);
  EXPECT_EQ(p.s(), 1.0);
  EXPECT_LE(max_speed(r), 10.0 + 1e-9);
  EXPECT_GE(max_speed(r), 9.5);
  EXPECT_NEAR(duration_estimate(1.0, 500.0, l), 0.2, 1e-12);
  EXPECT_NEAR(static_cast<double>(r.steps) * kDt, 0.2, 3 * kDt);
}

TEST(PathProfile, TinySegmentsFinishInFewCycles) {
  PathProfile p;
  const PathLimits l{1000.0, 1000.0, 1000.0};
  for (double len : {1e-8, 1e-6, 1e-3, 0.01}) {
    ASSERT_TRUE(p.start(len, 100.0, l));
    const Trace r = run_checked(p, 1.0, 1000);
    ASSERT_TRUE(r.finished) << len;
    EXPECT_EQ(p.s(), len);
    // Continuous triangle time 2 sqrt(L/a), plus two cycles for discretisation.
    EXPECT_LE(static_cast<double>(r.steps), 2 * std::sqrt(len / 1000.0) / kDt + 2.0) << len;
  }
}

TEST(PathProfile, ZeroLengthIsDoneAtOnce) {
  PathProfile p;
  EXPECT_TRUE(p.start(0.0, 100.0, PathLimits{100, 100, 100}));
  EXPECT_TRUE(p.finished());
  const ProfileSample smp = p.step(kDt, 1.0);
  EXPECT_TRUE(smp.finished);
  EXPECT_EQ(smp.s_mm, 0.0);
  EXPECT_EQ(smp.v_mm_s, 0.0);
  // Even with unusable limits: nothing has to move.
  EXPECT_TRUE(p.start(0.0, 0.0, PathLimits{}));
  EXPECT_EQ(duration_estimate(0.0, 10.0, PathLimits{}), 0.0);
}

TEST(PathProfile, InvalidInputIsRefusedNotFollowed) {
  PathProfile p;
  EXPECT_FALSE(p.start(10.0, 100.0, PathLimits{0, 100, 100}));
  EXPECT_TRUE(p.finished());
  EXPECT_EQ(p.s(), 0.0);
  EXPECT_FALSE(p.start(10.0, 0.0, PathLimits{100, 100, 100}));
  EXPECT_FALSE(p.start(10.0, NAN, PathLimits{100, 100, 100}));
  EXPECT_FALSE(p.start(NAN, 10.0, PathLimits{100, 100, 100}));
  EXPECT_FALSE(p.start(-1.0, 10.0, PathLimits{100, 100, 100}));
  EXPECT_FALSE(p.start(10.0, 10.0, PathLimits{100, 100, std::numeric_limits<double>::infinity()}));
  EXPECT_TRUE(std::isinf(duration_estimate(10.0, 10.0, PathLimits{})));
  // Bad dt or override never produce NaN and never move backwards.
  ASSERT_TRUE(p.start(10.0, 10.0, PathLimits{100, 100, 100}));
  for (double dt : {0.0, -1.0, std::nan("")}) {
    const ProfileSample smp = p.step(dt, 1.0);
    EXPECT_EQ(smp.s_mm, 0.0);
  }
  const ProfileSample smp = p.step(kDt, NAN);  // NaN override: hold
  EXPECT_EQ(smp.s_mm, 0.0);
  EXPECT_EQ(smp.v_mm_s, 0.0);
}

TEST(PathProfile, Override50Percent) {
  PathProfile p;
  const PathLimits l{200.0, 1000.0, 1000.0};
  ASSERT_TRUE(p.start(100.0, 50.0, l));
  const Trace r = run_checked(p, 0.5, 100000);
  ASSERT_TRUE(r.finished);
  EXPECT_NEAR(max_speed(r), 25.0, 1e-9);
  EXPECT_NEAR(static_cast<double>(r.steps) * kDt, duration_estimate(100.0, 25.0, l), 3 * kDt);
}

TEST(PathProfile, FeedholdMidMoveAndResume) {
  PathProfile p;
  const PathLimits l{100.0, 400.0, 800.0};
  ASSERT_TRUE(p.start(50.0, 60.0, l));
  Trace r = run_checked(p, 1.0, 400);  // 0.4 s: cruising at 60 mm/s
  ASSERT_FALSE(r.finished);
  EXPECT_NEAR(p.v(), 60.0, 1e-9);
  const double s_hold = p.s();
  // Feedhold: brakes at a_dec (60/800 = 0.075 s = 75 cycles) and stays.
  Trace hold = run_checked(p, 0.0, 75);
  EXPECT_EQ(p.v(), 0.0);
  // Distance while braking from 60 at 800 mm/s^2 in 1 ms steps: 59.2+...+0 = 2.22 mm.
  EXPECT_NEAR(p.s() - s_hold, 60.0 * 60.0 / (2 * 800.0), 0.05);
  const double s_stopped = p.s();
  hold = run_checked(p, 0.0, 2000);
  EXPECT_EQ(p.s(), s_stopped);  // holds for 2 s without creeping
  EXPECT_FALSE(p.finished());
  // Resume: reaches the end exactly.
  r = run_checked(p, 1.0, 100000);
  ASSERT_TRUE(r.finished);
  EXPECT_EQ(p.s(), 50.0);
}

TEST(PathProfile, FeedholdDuringFinalBrakingStillEndsExactly) {
  PathProfile p;
  const PathLimits l{100.0, 1000.0, 1000.0};
  ASSERT_TRUE(p.start(10.0, 100.0, l));
  run_checked(p, 1.0, 60);  // speeding up, not yet on the braking curve
  run_checked(p, 0.0, 500);
  EXPECT_EQ(p.v(), 0.0);
  EXPECT_LT(p.s(), 10.0);
  const Trace r = run_checked(p, 0.3, 100000);
  ASSERT_TRUE(r.finished);
  EXPECT_EQ(p.s(), 10.0);
}

TEST(PathProfile, OverrideChangesMidMove) {
  PathProfile p;
  const PathLimits l{100.0, 300.0, 300.0};
  ASSERT_TRUE(p.start(200.0, 80.0, l));
  run_checked(p, 1.0, 500);
  run_checked(p, 0.25, 500);
  EXPECT_NEAR(p.v(), 20.0, 1e-9);
  run_checked(p, 1.2, 500);
  EXPECT_NEAR(p.v(), 96.0, 1e-9);
  const Trace r = run_checked(p, 1.2, 100000);
  ASSERT_TRUE(r.finished);
  EXPECT_EQ(p.s(), 200.0);
}

TEST(PathProfile, EndVelocityCarriesIntoNextSegment) {
  // Two 50 mm segments blended at full speed take as long as one 100 mm move.
  PathProfile p;
  const PathLimits l{100.0, 500.0, 500.0};
  ASSERT_TRUE(p.start(50.0, 50.0, l, 50.0));
  Trace first = run_checked(p, 1.0, 100000);
  ASSERT_TRUE(first.finished);
  EXPECT_NEAR(p.v(), 50.0, 1e-9);  // did not slow down
  ASSERT_TRUE(p.start(50.0, 50.0, l));
  EXPECT_GT(p.s(), 0.0 - 1e-12);  // carried overshoot of the first segment
  Trace second = run_checked(p, 1.0, 100000);
  ASSERT_TRUE(second.finished);
  EXPECT_EQ(p.s(), 50.0);
  const double t = static_cast<double>(first.steps + second.steps) * kDt;
  EXPECT_NEAR(t, duration_estimate(100.0, 50.0, l), 3 * kDt);
}

// A feedhold that stopped the path just before the end of a segment it
// passes on from: the step out of the standstill reaches the end and no
// further (its speed-up is this segment's; the next segment's direction may
// turn it into more than an axis's a_max), and nothing is carried.
TEST(PathProfile, OutOfAStandstillJustBeforeAPassedEndTheStepStopsThere) {
  PathProfile p;
  const PathLimits l{100.0, 2500.0, 2500.0};
  ASSERT_TRUE(p.start(1.0, 50.0, l, 40.0));
  // Hold at once: from standstill nothing moves; then creep to 0.7 um before the end.
  ASSERT_EQ(p.step(kDt, 0.0).v_mm_s, 0.0);
  ASSERT_TRUE(p.start(0.0007, 50.0, l, 40.0));  // what is left of the block
  const ProfileSample st = p.step(kDt, 1.0);
  EXPECT_TRUE(st.finished);
  EXPECT_NEAR(st.v_mm_s, 0.7, 1e-9);  // not 2.5 (a * dt), of which 1.8 um would lie in the next segment
  ASSERT_TRUE(p.start(10.0, 50.0, l));
  EXPECT_EQ(p.s(), 0.0);  // nothing carried
  EXPECT_LE(p.step(kDt, 1.0).v_mm_s, 0.7 + 2.5 + 1e-9);
}

TEST(PathProfile, EndVelocityBrakesDownToIt) {
  PathProfile p;
  const PathLimits l{100.0, 500.0, 500.0};
  ASSERT_TRUE(p.start(40.0, 80.0, l, 20.0));
  const Trace r = run_checked(p, 1.0, 100000);
  ASSERT_TRUE(r.finished);
  // The last full cycle runs at v_end (within one acceleration step); the final
  // one is partial, its rest is carried into the next segment.
  ASSERT_GE(r.s.size(), 3u);
  EXPECT_NEAR((r.s[r.s.size() - 2] - r.s[r.s.size() - 3]) / kDt, 20.0, 2 * 500.0 * kDt);
  // Discrete braking curve: the final cycle runs within one step above v_end.
  EXPECT_GE(p.v(), 20.0 - 1e-9);
  EXPECT_LE(p.v(), 20.0 + 500.0 * kDt);
}

// Into a fillet (corner blending, issue 30) the cycle that crosses the end
// runs at v_end exactly and may itself be the last braking step; without
// pass_into_fillet the profile holds v_end a cycle before it. For lengths
// that put the end at every phase of the braking staircase: the crossing
// cycle at v_end, no step beyond a_dec, never slower than the plain profile
// (and at some lengths a cycle faster).
TEST(PathProfile, PassIntoFilletBrakesInTheCrossingCycle) {
  const PathLimits l{100.0, 500.0, 500.0};
  std::size_t faster = 0;
  for (int i = 0; i < 40; ++i) {
    const double length = 10.0 + 0.0013 * i;
    PathProfile into, plain;
    ASSERT_TRUE(into.start(length, 80.0, l, 20.0));
    into.pass_into_fillet();
    ASSERT_TRUE(plain.start(length, 80.0, l, 20.0));
    const Trace r = run_checked(into, 1.0, 100000), q = run_checked(plain, 1.0, 100000);
    ASSERT_TRUE(r.finished && q.finished);
    EXPECT_NEAR(into.v(), 20.0, 1e-9) << length;
    EXPECT_LE(r.steps, q.steps) << length;
    if (r.steps < q.steps || r.s[r.s.size() - 2] > q.s[q.s.size() - 2] + 1e-9) ++faster;
  }
  EXPECT_GT(faster, 0u);
}

// Braking across the end (issue 43): besides the ceiling v_end (20), the
// profile follows the staircase to standstill 0.2 mm past the end, so it
// passes on slower than the ceiling, and no step brakes beyond a_dec; the
// crossing cycle brakes on rather than holding. Without it, it passes at
// the ceiling.
TEST(PathProfile, BrakeThroughFollowsTheStaircaseAcrossTheEnd) {
  const PathLimits l{100.0, 500.0, 500.0};
  PathProfile across, plain;
  ASSERT_TRUE(across.start(10.0, 80.0, l, 20.0));
  across.brake_through(0.2);
  ASSERT_TRUE(plain.start(10.0, 80.0, l, 20.0));
  const Trace r = run_checked(across, 1.0, 100000), q = run_checked(plain, 1.0, 100000);
  ASSERT_TRUE(r.finished && q.finished);
  // The crossing cycle starts within one cycle's travel of the end, where the
  // staircase allows about 14 mm/s; it brakes on rather than holding.
  EXPECT_LE(across.v(), discrete_brake_velocity(0.2 + across.v() * kDt, 500.0, kDt) + 1e-9);
  EXPECT_GT(across.v(), discrete_brake_velocity(0.2, 500.0, kDt) - 2 * 500.0 * kDt);
  EXPECT_NEAR(plain.v(), 20.0, 500.0 * kDt);
  // A staircase beyond the ceiling's reach changes nothing.
  PathProfile far;
  ASSERT_TRUE(far.start(10.0, 80.0, l, 20.0));
  far.brake_through(100.0);
  const Trace f = run_checked(far, 1.0, 100000);
  EXPECT_EQ(f.steps, q.steps);
  EXPECT_DOUBLE_EQ(far.v(), plain.v());
}

}  // namespace
}  // namespace nck::motion
