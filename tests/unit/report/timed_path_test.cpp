// The report's timed tool path (timed_path.hpp): every cycle's position
// within the tolerance of the interpolation in time, and every segment in
// the block its end names (issue 48 item 1).
#include "nck/report/timed_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace nck::app {
namespace {

constexpr double kCycleS = 0.001;

// What the page's cursor does at time t: interpolate between the vertices
// around t, named by the later one (player.js, toolAt).
struct At {
  std::array<double, 3> pos;
  std::uint32_t line;
};
At cursor(std::span<const TimedPoint> v, double t) {
  std::size_t j = 1;
  while (j < v.size() - 1 && v[j].t_s < t) ++j;
  const TimedPoint &a = v[j - 1], &b = v[j];
  if (t <= a.t_s) return {a.pos, a.line};
  const double f = std::min(1.0, (t - a.t_s) / (b.t_s - a.t_s));
  At at{{}, b.line};
  for (int k = 0; k < 3; ++k) at.pos[k] = a.pos[k] + f * (b.pos[k] - a.pos[k]);
  return at;
}

// Every sample against the cursor over the vertices: its block, and its
// position within the stated error.
void expect_cursor_matches(const std::vector<TimedPoint>& samples, const TimedPath::Vertices& v) {
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const TimedPoint& s = samples[i];
    const At at = cursor(v.points, s.t_s);
    if (v.by_block) {
      ASSERT_EQ(at.line, s.line) << "t " << s.t_s;
    }
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(at.pos[k], s.pos[k], v.error_mm + 1e-12) << "t " << s.t_s << " axis " << k;
  }
}

TEST(TimedPath, ConstantFeedLinesBecomeTheirBlocksLastCycles) {
  TimedPath p;
  std::vector<TimedPoint> samples;
  auto add = [&](TimedPoint s) { samples.push_back(s); p.add(s); };
  add({.pos = {0, 0, 0}, .t_s = 0});
  for (int i = 1; i <= 1000; ++i) add({.pos = {i * 0.01, 0, 0}, .t_s = i * kCycleS, .line = 1});
  for (int i = 1; i <= 500; ++i) add({.pos = {10 + i * 0.01, 0, 0}, .t_s = (1000 + i) * kCycleS, .line = 2});  // collinear
  const TimedPath::Vertices v = p.vertices(1000);
  ASSERT_EQ(v.points.size(), 3u);  // the start, N1's last cycle, N2's last cycle
  EXPECT_DOUBLE_EQ(v.points[1].pos[0], 10);
  EXPECT_EQ(v.points[1].line, 1u);
  EXPECT_EQ(v.points[2].line, 2u);
  EXPECT_TRUE(v.by_block);
  expect_cursor_matches(samples, v);
}

// Accelerating: a line (in space) is many segments in time; the geometric
// thinning of before made one of it and its DRO ran up to mm off.
TEST(TimedPath, AccelerationKeepsTheTimingWithinTheTolerance) {
  TimedPath p;
  std::vector<TimedPoint> samples;
  for (int i = 0; i <= 2000; ++i) {
    const double t = i * kCycleS, x = 0.5 * 20 * t * t;  // 20 mm/s²
    samples.push_back({.pos = {x, 2 * x, 0}, .t_s = t, .line = 7});
    p.add(samples.back());
  }
  const TimedPath::Vertices v = p.vertices(100000);
  // a chord over h seconds misses a parabola by a h² / 8: at 40 mm/s² and
  // 0.1 µm, a vertex every 4 cycles (h <= 4.5 ms)
  EXPECT_LE(v.points.size(), samples.size() / 4 + 2);
  EXPECT_GT(v.points.size(), 10u);
  EXPECT_DOUBLE_EQ(v.error_mm, TimedPath::kTolMm);
  expect_cursor_matches(samples, v);
}

// An arc, then a dwell whose block changes with the tool standing still,
// then another block: each named at its own cycles.
TEST(TimedPath, ArcsAndBlocksWithoutMotionKeepTheirCycles) {
  TimedPath p;
  std::vector<TimedPoint> samples;
  double t = 0;
  for (int i = 0; i <= 3142; ++i, t += kCycleS)
    samples.push_back({.pos = {10 * std::cos(i * 0.001), 10 * std::sin(i * 0.001), 0}, .t_s = t, .line = 3});
  const auto end = samples.back().pos;
  for (int i = 0; i < 200; ++i, t += kCycleS) samples.push_back({.pos = end, .t_s = t, .line = 4});  // G4
  for (int i = 1; i <= 100; ++i, t += kCycleS)
    samples.push_back({.pos = {end[0], end[1], -0.05 * i}, .t_s = t, .line = 5, .rapid = true});
  for (const TimedPoint& s : samples) p.add(s);
  const TimedPath::Vertices v = p.vertices(100000);
  expect_cursor_matches(samples, v);
  EXPECT_DOUBLE_EQ(p.max()[0], 10);
  EXPECT_NEAR(p.min()[2], -5, 1e-12);
}

// More blocks than the page may show: thinned across blocks, with a
// larger bound stated, and never more than asked for.
TEST(TimedPath, ThinnedToTheCapWithItsBoundStated) {
  TimedPath p;
  std::vector<TimedPoint> samples;
  for (int i = 0; i < 20000; ++i) {
    const double t = i * kCycleS;
    samples.push_back({.pos = {std::sin(t), std::cos(3 * t), 0}, .t_s = t, .line = static_cast<std::uint32_t>(i / 4)});
    p.add(samples.back());
  }
  const TimedPath::Vertices v = p.vertices(1000);
  EXPECT_LE(v.points.size(), 1000u);
  EXPECT_FALSE(v.by_block);
  EXPECT_GT(v.error_mm, TimedPath::kTolMm);
  expect_cursor_matches(samples, v);
  EXPECT_DOUBLE_EQ(v.points.back().t_s, samples.back().t_s);
}

// Beyond kMaxVertices while recording: thinned in place, the bound grows,
// every cycle still within it and the newest one kept.
TEST(TimedPath, LongRunsStayBoundedWhileRecording) {
  TimedPath p;
  std::vector<TimedPoint> samples;
  const std::size_t n = 2 * TimedPath::kMaxVertices + 10;
  samples.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * kCycleS;
    samples.push_back({.pos = {static_cast<double>(i % 2) * 0.01, 0, 0}, .t_s = t, .line = static_cast<std::uint32_t>(i / 100)});
    p.add(samples.back());
  }
  const TimedPath::Vertices v = p.vertices(TimedPath::kMaxVertices + 1);
  EXPECT_LE(v.points.size(), TimedPath::kMaxVertices + 1);
  EXPECT_GT(v.error_mm, TimedPath::kTolMm);
  expect_cursor_matches(samples, v);
}

}  // namespace
}  // namespace nck::app
