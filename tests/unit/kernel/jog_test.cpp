// Manual mode (issue 27): a jog ramps within the axis's manual-mode
// acceleration, stops at the software limit without passing it, lands an
// increment exactly, and is refused while the program moves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "../../../src/kernel/units/jog_unit.hpp"
#include "nck/motion/path_profile.hpp"
#include "test_machine.hpp"
#include "../seen_events.hpp"

namespace nck::kernel {
namespace {

using testing::end_block;
using testing::move;
using testing::xyz_machine;

constexpr double kDt_s = 0.001;
constexpr double kJogAMax_mm_s2 = 800;  // P-AXIS-00009, below the axes' a_max (2000)

config::Machine jog_machine(double sw_limit_pos_mm = 10000) {
  config::Machine m = xyz_machine(500, 2000);
  for (auto& ax : m.axes) {
    ax.manual_a_max_mm_s2 = kJogAMax_mm_s2;
    ax.sw_limit_pos = sw_limit_pos_mm;
    ax.sw_limit_neg = -sw_limit_pos_mm;
  }
  return m;
}

JogRequest jog(JogRequest::Kind kind, std::int8_t direction, double speed_mm_s = 0, double step_mm = 0) {
  JogRequest r;
  r.kind = kind;
  r.axis = 0;
  r.direction = direction;
  r.speed_mm_s = speed_mm_s;
  r.step_mm = step_mm;
  return r;
}

// A kernel without a program (idle: jogs are allowed) and X's motion.
struct Rig {
  explicit Rig(const config::Machine& machine) : m(std::make_unique<config::Machine>(machine)) {
    EXPECT_TRUE(k.configure(*m));
  }
  // One cycle, with request r if given; X's machine set point after it.
  double tick(std::optional<JogRequest> r = {}) {
    in->channels[0].jogs.clear();
    if (r) (void)in->channels[0].jogs.push_back(*r);
    k.tick(*in, *out);
    const double x = out->channels[0].axis_mcs[0];
    const double v = (x - x_) / kDt_s;
    worst_a_ = std::max(worst_a_, std::abs(v - v_) / kDt_s);
    top_v_ = std::max(top_v_, std::abs(v));
    highest_x_ = std::max(highest_x_, x);
    for (const Event& e : out->events)
      if (e.kind() == EventKind::warning) warnings.push_back(test::diagnosis_id(e));
    x_ = x;
    v_ = v;
    return x;
  }
  void run_until_still(int max_cycles = 100000) {
    for (int i = 0; i < max_cycles && (k.channel_jogging(0) || i == 0); ++i) tick();
  }

  std::unique_ptr<config::Machine> m;
  Kernel k;
  std::unique_ptr<TickInput> in = std::make_unique<TickInput>();
  std::unique_ptr<TickOutput> out = std::make_unique<TickOutput>();
  std::vector<ErrorId> warnings;
  double x_ = 0, v_ = 0, worst_a_ = 0, top_v_ = 0, highest_x_ = -1e300;
};

TEST(Jog, ContinuousRampsWithinManualAMaxAndStopsWhenReleased) {
  Rig r(jog_machine());
  r.tick(jog(JogRequest::Kind::continuous, +1, 50.0));
  for (int i = 0; i < 1000; ++i) r.tick();
  EXPECT_TRUE(r.k.channel_jogging(0));
  EXPECT_NEAR(r.v_, 50.0, 1e-9);  // reached its speed (50 mm/s after 62.5 ms)
  const double x_release = r.x_;
  r.tick(jog(JogRequest::Kind::stop, +1));
  r.run_until_still();
  EXPECT_FALSE(r.k.channel_jogging(0));
  EXPECT_EQ(r.v_, 0.0);
  EXPECT_LE(r.worst_a_, kJogAMax_mm_s2 * (1 + 1e-9));
  EXPECT_GE(r.worst_a_, kJogAMax_mm_s2 * (1 - 1e-9));  // the ramp used the manual-mode a_max, not the axis's 2000
  EXPECT_NEAR(r.top_v_, 50.0, 1e-9);
  // braking from 50 mm/s at 800 mm/s^2 takes about v^2 / 2a = 1.5625 mm
  EXPECT_NEAR(r.x_ - x_release, 50.0 * 50.0 / (2 * kJogAMax_mm_s2), 0.05);
  EXPECT_TRUE(r.warnings.empty());
  // the travel is the channel's manual offset (kept for the program)
  EXPECT_NEAR(r.k.channel_state(0).manual_offsets[0], r.x_, 1e-12);
}

// P-CHAN-00181 ACTIVE_EXTENDED: the rapid override scales a continuous
// jog (50 % of 50 mm/s); other modes leave the jog at its speed.
TEST(Jog, RapidOverrideScalesAContinuousJogUnderActiveExtendedOnly) {
  for (const auto& [mode, speed_mm_s] : {std::pair{RapidOverrideMode::active_extended, 25.0},
                                        std::pair{RapidOverrideMode::active, 50.0},
                                        std::pair{RapidOverrideMode::not_used, 50.0}}) {
    config::Machine m = jog_machine();
    m.channels[0].rapid_override_mode = mode;
    Rig r(m);
    r.in->channels[0].rapid_override_pct = 50;
    r.tick(jog(JogRequest::Kind::continuous, +1, 50.0));
    for (int i = 0; i < 1000; ++i) r.tick();
    EXPECT_NEAR(r.v_, speed_mm_s, 1e-9) << static_cast<int>(mode);
    r.in->channels[0].rapid_override_pct = 0;  // held, not ended
    for (int i = 0; i < 200; ++i) r.tick();
    EXPECT_TRUE(r.k.channel_jogging(0));
    EXPECT_NEAR(r.v_, mode == RapidOverrideMode::active_extended ? 0.0 : 50.0, 1e-9);
  }
}

TEST(Jog, StopsAtTheSoftLimitWithoutPassingIt) {
  Rig r(jog_machine(10.0));
  r.tick(jog(JogRequest::Kind::continuous, +1, 200.0));
  r.run_until_still();
  EXPECT_FALSE(r.k.channel_jogging(0));
  EXPECT_LE(r.highest_x_, 10.0 + 1e-12);  // never beyond the limit (but for a double's rounding)
  EXPECT_NEAR(r.x_, 10.0, 1e-12);         // and it stands at it
  EXPECT_LE(r.worst_a_, kJogAMax_mm_s2 * (1 + 1e-6));
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0], ErrorId::KernelJogSoftLimit);
  // the channel stays usable: a jog away from the limit moves
  r.tick(jog(JogRequest::Kind::increment, -1, 0, 1.0));
  r.run_until_still();
  EXPECT_NEAR(r.x_, 9.0, 1e-9);
  // an increment beyond the limit stops at it, with the warning again
  r.tick(jog(JogRequest::Kind::increment, +1, 0, 5.0));
  r.run_until_still();
  EXPECT_LE(r.highest_x_, 10.0 + 1e-12);
  EXPECT_NEAR(r.x_, 10.0, 1e-12);
  EXPECT_EQ(r.warnings.size(), 2u);
  // at the limit, towards it: the warning, nothing moves
  r.tick(jog(JogRequest::Kind::continuous, +1, 5.0));
  r.run_until_still();
  EXPECT_NEAR(r.x_, 10.0, 1e-12);
  EXPECT_EQ(r.warnings.size(), 3u);
}

TEST(Jog, IncrementLandsExactly) {
  Rig r(jog_machine());
  r.tick(jog(JogRequest::Kind::increment, +1, 0, 0.5));
  r.run_until_still();
  EXPECT_NEAR(r.x_, 0.5, 1e-12);
  r.tick(jog(JogRequest::Kind::increment, -1, 0, 0.2));
  r.run_until_still();
  EXPECT_NEAR(r.x_, 0.3, 1e-12);
  // two presses in a row: two steps
  r.tick(jog(JogRequest::Kind::increment, +1, 0, 1.0));
  r.tick(jog(JogRequest::Kind::increment, +1, 0, 1.0));
  r.run_until_still();
  EXPECT_NEAR(r.x_, 2.3, 1e-12);
  EXPECT_LE(r.worst_a_, kJogAMax_mm_s2 * (1 + 1e-6));
  // at the incremental jog speed (P-AXIS-00076, default 16.666 mm/s)
  EXPECT_LE(r.top_v_, 16.666 + 1e-9);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(Jog, ReversalBrakesWithinAMax) {
  Rig r(jog_machine());
  r.tick(jog(JogRequest::Kind::continuous, +1, 40.0));
  for (int i = 0; i < 200; ++i) r.tick();
  r.tick(jog(JogRequest::Kind::continuous, -1, 40.0));
  for (int i = 0; i < 300; ++i) r.tick();
  EXPECT_NEAR(r.v_, -40.0, 1e-9);
  EXPECT_LE(r.worst_a_, kJogAMax_mm_s2 * (1 + 1e-6));
}

TEST(Jog, BadRequestIsIgnoredWithItsId) {
  Rig r(jog_machine());
  JogRequest bad = jog(JogRequest::Kind::increment, +1, 0, 0.0);  // no step
  r.tick(bad);
  bad = jog(JogRequest::Kind::continuous, +1, 10.0);
  bad.axis = 7;  // the channel has 3 axes
  r.tick(bad);
  EXPECT_FALSE(r.k.channel_jogging(0));
  EXPECT_EQ(r.x_, 0.0);
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_EQ(r.warnings[0], ErrorId::KernelJogBadRequest);
  EXPECT_EQ(r.warnings[1], ErrorId::KernelJogBadRequest);
}

TEST(Jog, RefusedWhileTheProgramMoves) {
  const config::Machine m = jog_machine();
  Kernel k;
  ASSERT_TRUE(k.configure(m));
  prep::PlanStore store;
  prep::ChannelPrep prep(m, 0, "", store, prep::PrepOptions{});
  ASSERT_TRUE(prep.prepare(move(1, nc::Motion::linear, 100.0, {}, {}, 3000), k.commands(0)));
  ASSERT_TRUE(prep.prepare(end_block(2), k.commands(0)));
  auto in = std::make_unique<TickInput>();
  auto out = std::make_unique<TickOutput>();
  int refused = 0;
  bool ended = false;
  for (int cycle = 0; cycle < 100000 && !ended; ++cycle) {
    in->channels[0].jogs.clear();
    if (cycle == 100) (void)in->channels[0].jogs.push_back(jog(JogRequest::Kind::continuous, +1, 10.0));
    k.tick(*in, *out);
    if (cycle == 100) {
      EXPECT_EQ(out->channels[0].program_state, ProgramState::running);
    }
    for (const Event& e : out->events) {
      if (test::diagnosis_id(e) == ErrorId::KernelJogRefused) ++refused;
      if (e.kind() == EventKind::end) ended = true;
      EXPECT_NE(e.kind(), EventKind::error);
    }
    EXPECT_FALSE(k.channel_jogging(0));
  }
  ASSERT_TRUE(ended);
  EXPECT_EQ(refused, 1);
  // nothing changed: no manual offset, the program's end point
  EXPECT_EQ(k.channel_state(0).manual_offsets[0], 0.0);
  EXPECT_NEAR(k.channel_state(0).axis_mcs[0], 100.0, 1e-9);
}

TEST(Jog, BrakingSpeedStopsWithinTheDistance) {
  // The jog's braking cap (the path's staircase, motion/path_profile.hpp).
  // Following the cap from full speed, each cycle covering min(v dt, rest):
  // the speed never drops by more than a dt, the rest never goes negative,
  // and the axis comes to the end in finitely many cycles.
  constexpr double kA = 800;
  for (double d : {1e-9, 0.001, 0.37, 5.0, 123.4}) {
    double rest = d, v_prev = motion::discrete_brake_velocity(d, kA, kDt_s);
    int cycles = 0;
    for (; rest > 0 && cycles < 100000; ++cycles) {
      const double v = std::min(v_prev + kA * kDt_s, motion::discrete_brake_velocity(rest, kA, kDt_s));
      const double step = std::min(v * kDt_s, rest);
      EXPECT_LE(v_prev - step / kDt_s, kA * kDt_s * (1 + 1e-9)) << d << " at " << rest;
      rest -= step;
      v_prev = step / kDt_s;
    }
    EXPECT_EQ(rest, 0.0) << d;
    EXPECT_LT(cycles, 100000) << d;
  }
  EXPECT_EQ(motion::discrete_brake_velocity(0.0, kA, kDt_s), 0.0);
  EXPECT_EQ(motion::discrete_brake_velocity(-1.0, kA, kDt_s), 0.0);
}

}  // namespace
}  // namespace nck::kernel
