// The kernel's braking reserve (issue 24): preparation in a thread of its
// own that falls behind must never make the machine jerk. A producer thread
// plans a polygon of short chords (passed at speed: the look-ahead plans
// each chord's end speed from the chords after it in its window) much more
// slowly than the kernel runs; the kernel must brake within what is queued,
// stay within every axis's max_speed_mm_s and a_max in every cycle, never jump,
// resume from the real speed, warn once per episode (930600), and still
// reach the end.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <thread>

#include "nck/kernel/braking_reserve.hpp"
#include "nck/motion/path_profile.hpp"
#include "test_machine.hpp"
#include "../seen_events.hpp"

namespace nck::kernel {
namespace {

using testing::end_block;
using testing::move;
using testing::xyz_machine;

constexpr double kVbMax_mm_s = 500, kAMax_mm_s2 = 2000;
constexpr int kChords = 120;

// Chord i of a circle of radius 40 mm (1.05 mm long, 3 degrees between
// neighbours: passed at speed).
nc::Block chord(int i) {
  const double a = 2.0 * std::numbers::pi * i / kChords;
  return move(static_cast<std::uint32_t>(i + 1), nc::Motion::linear, 40 * std::cos(a) - 40, 40 * std::sin(a), {},
              9000);
}

struct Rig {
  Rig() : m(std::make_unique<config::Machine>(xyz_machine(kVbMax_mm_s, kAMax_mm_s2))) {
    m->channels[0].lookahead_blocks = 16;
    // Headroom between the path's and the axes' acceleration: kinks are
    // passed at speed (with accel_mm_s2 = a_max every kink is an exact stop).
    for (auto& ax : m->axes)
      for (auto& g : ax.gears) g.accel_mm_s2 = g.decel_mm_s2 = 0.5 * kAMax_mm_s2;
    EXPECT_TRUE(k.configure(*m));
    prep.emplace(*m, 0, "", store, prep::PrepOptions{});
  }
  void push(const nc::Block& b) { EXPECT_TRUE(prep->prepare(b, k.commands(0))); }

  std::unique_ptr<config::Machine> m;
  Kernel k;
  prep::PlanStore store;
  std::optional<prep::ChannelPrep> prep;
};

struct Observed {
  int starved_warnings = 0;
  double worst_v_ratio = 0, worst_a_ratio = 0;  // |v| / max_speed_mm_s, |a| / a_max over all axes and cycles
  double reported_v_when_standing_mm_s = 0;     // path velocity reported in a cycle without motion
  int standing_cycles = 0;  // between the first motion and the program end, the axes stood
  motion::AxisVector end{};
  bool ended = false;
};

// Ticks the kernel until the program ends (or a cycle limit), checking every cycle.
Observed tick_until_end(Rig& r) {
  Observed o;
  auto in = std::make_unique<TickInput>();
  auto out = std::make_unique<TickOutput>();
  const double dt = 0.001;
  std::array<double, 3> prev{}, prev_v{};
  bool first = true, started = false;
  for (int cycle = 0; cycle < 20'000'000 && !o.ended; ++cycle) {
    r.k.tick(*in, *out);
    for (const Event& e : out->events) {
      if (test::diagnosis_id(e) == ErrorId::KernelPrepStarved) ++o.starved_warnings;
      if (e.kind() == EventKind::end) o.ended = true;
    }
    const ChannelOutput& c = out->channels[0];
    bool moved = false;
    for (std::size_t j = 0; j < 3; ++j) {
      const double v = (c.axis_mcs[j] - prev[j]) / dt;
      if (!first) {
        o.worst_v_ratio = std::max(o.worst_v_ratio, std::abs(v) / kVbMax_mm_s);
        o.worst_a_ratio = std::max(o.worst_a_ratio, std::abs(v - prev_v[j]) / dt / kAMax_mm_s2);
      }
      moved = moved || c.axis_mcs[j] != prev[j];
      prev_v[j] = v;
      prev[j] = c.axis_mcs[j];
    }
    if (!moved && !first) o.reported_v_when_standing_mm_s = std::max(o.reported_v_when_standing_mm_s, c.path_velocity_mm_s);
    if (!moved && started && !o.ended) ++o.standing_cycles;
    started = started || moved;
    first = false;
    o.end = c.axis_mcs;
  }
  return o;
}

TEST(BrakingReserve, SlowProducerThreadNeverBreaksALimit) {
  Rig r;
  std::jthread producer([&] {
    for (int i = 0; i < kChords; ++i) {
      r.push(chord(i));
      std::this_thread::sleep_for(std::chrono::microseconds(300));  // far slower than the kernel's cycles
    }
    r.push(end_block(kChords + 1));
  });
  const Observed o = tick_until_end(r);
  producer.join();
  ASSERT_TRUE(o.ended);
  EXPECT_GE(o.starved_warnings, 1);
  EXPECT_GT(o.standing_cycles, 10);  // the path stopped where preparation had nothing queued
  EXPECT_LE(o.worst_v_ratio, 1.0 + 1e-9);
  EXPECT_LE(o.worst_a_ratio, 1.0 + 1e-6);
  EXPECT_EQ(o.reported_v_when_standing_mm_s, 0.0);  // the axes stand: so does the reported path
  const nc::Block last = chord(kChords - 1);
  EXPECT_NEAR(o.end[0], *last.axes[0], 1e-9);
  EXPECT_NEAR(o.end[1], *last.axes[1], 1e-9);
}

// The counter-case: everything queued before the first cycle runs as planned.
TEST(BrakingReserve, PreparationThatKeepsUpIsNeverStarved) {
  Rig r;
  for (int i = 0; i < kChords; ++i) r.push(chord(i));
  r.push(end_block(kChords + 1));
  const Observed o = tick_until_end(r);
  ASSERT_TRUE(o.ended);
  EXPECT_EQ(o.starved_warnings, 0);
  EXPECT_LE(o.worst_a_ratio, 1.0 + 1e-6);
  EXPECT_LE(o.standing_cycles, 1);  // the chords are passed at speed (the last cycle may stand)
}

// The reserve is not a second planner: with a successor queued the end speed
// is the planned one, without any it is standstill, and with a short queue
// it is what braking within the queued path allows.
TEST(BrakingReserve, EndSpeedFollowsTheQueuedPath) {
  auto q = std::make_unique<CommandQueue>();
  Motion cur;
  cur.v_end_mm_s = 100;
  cur.limits.a_dec_mm_s2 = 1000;
  EXPECT_EQ(reserve_end_speed(cur, *q, 0.001), 0.0);
  Motion next_motion = cur;
  next_motion.path = motion::make_line({}, motion::AxisVector{1.0}, 1)->tail();  // 1 mm: too short to stop from 100 mm/s
  Command next;
  next.action = next_motion;
  ASSERT_TRUE(q->push(next));
  const double v = reserve_end_speed(cur, *q, 0.001);
  EXPECT_GT(v, 0.0);
  EXPECT_LT(v, 100.0);
  EXPECT_NEAR(motion::discrete_brake_distance(v, 1000, 0.001), 1.0, 0.1);
  Command stop;
  stop.action = Dwell{};  // a planned stop follows: the planner's speed holds
  ASSERT_TRUE(q->push(stop));
  EXPECT_EQ(reserve_end_speed(cur, *q, 0.001), 100.0);
}

}  // namespace
}  // namespace nck::kernel
