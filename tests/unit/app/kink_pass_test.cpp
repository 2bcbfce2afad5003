// Kinks passed at speed under STEP where the feed accelerations equal a_max
// (issue 43, D2), through `nck run` on bench/machines/equal-limits
// (a_beschl = a_brems = a_grenz = a_max = 2,500 mm/s^2 on X, Y, Z, 1 ms).
// Before, a kink had only what a_max leaves above the feed acceleration,
// zero there: every kink of a fine polyline was a stop. Now the crossing
// cycle and the one before it keep the speed, so the turn may take half of
// a_max and the first step after it the rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "spindle_path_helpers.hpp"

namespace nck::app::testing {
namespace {

constexpr double kAMaxMmS2 = 2500;
// A second difference of the 6-decimal trace carries up to 2e-6 mm: 2 mm/s^2.
constexpr double kAccelRoundingMmS2 = 2;

std::string equal_limits() { return root() + "/bench/machines/equal-limits"; }

// n chords of length_mm in X/Y, turning by +kink and -kink in turn (a zigzag
// around the X axis), at feed_mm_min; every end point is returned.
std::string zigzag(int n, double length_mm, double kink_deg, double feed_mm_min,
                   std::vector<std::pair<double, double>>& points) {
  std::ostringstream p;
  p.precision(10);
  p << "%zigzag\nN10 G90 G17 G0 X0 Y0 Z0\nN20 G1 F" << feed_mm_min << "\n";
  double x = 0, y = 0;
  const double half = kink_deg / 2 * M_PI / 180;
  for (int i = 0; i < n; ++i) {
    const double a = i % 2 == 0 ? half : -half;
    x += length_mm * std::cos(a);
    y += length_mm * std::sin(a);
    points.emplace_back(x, y);
    p << "X" << x << " Y" << y << "\n";
  }
  p << "M30\n";
  return p.str();
}

double largest_acceleration(const PathRun& r) {
  double worst = 0;
  for (std::size_t i = 2; i < r.rows.size(); ++i)
    for (const char* axis : {"X", "Y", "Z"}) {
      const double a = (r.rows[i].at(axis) - 2 * r.rows[i - 1].at(axis) + r.rows[i - 2].at(axis)) / (kDt * kDt);
      worst = std::max(worst, std::abs(a));
    }
  return worst;
}

// The row nearest to (x, y) and its distance.
std::pair<std::size_t, double> nearest_row(const PathRun& r, double x, double y) {
  std::pair<std::size_t, double> best{0, 1e300};
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const double d = std::hypot(r.rows[i].at("X") - x, r.rows[i].at("Y") - y);
    if (d < best.second) best = {i, d};
  }
  return best;
}

double nearest(const PathRun& r, double x, double y) { return nearest_row(r, x, y).second; }

// The path speed of the cycle that ends at row i (mm/s).
double speed(const PathRun& r, std::size_t i) {
  return std::hypot(r.rows[i].at("X") - r.rows[i - 1].at("X"), r.rows[i].at("Y") - r.rows[i - 1].at("Y")) / kDt;
}

TEST(KinkPass, FineChordsAtEqualLimitsPassTheirKinksAtTheFeed) {
  // 300 chords of 0.5 mm, 1 degree kinks, F3000 (50 mm/s): a kink turns an
  // axis by 50 * 0.01745 = 0.87 mm/s in a cycle, 873 mm/s^2, within half of a_max.
  std::vector<std::pair<double, double>> points;
  const PathRun r = run_text(equal_limits(), zigzag(300, 0.5, 1.0, 3000, points), "kink_pass_chords");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const double start_s = r.line_t(4), end_s = r.line_t(304);  // the first chord, M30
  ASSERT_GE(start_s, 0);
  ASSERT_GT(end_s, start_s);
  // Ideal 150 mm / 50 mm/s = 3 s; speeding up from and braking to a stop
  // take 20 ms each (v / a), half of which is lost: 3.02 s and a cycle or two.
  EXPECT_LE(end_s - start_s, 3.0 + 0.02 + 0.003);
  // The kinks stay on the path: each end point within a cycle's travel of a set point.
  for (const auto& [x, y] : points) ASSERT_LE(nearest(r, x, y), 0.05 + 1e-6) << x << " " << y;
  EXPECT_LE(largest_acceleration(r), kAMaxMmS2 + kAccelRoundingMmS2);
}

TEST(KinkPass, ARightAngleStillStops) {
  // 90 degree kinks at F6000: Y turns by 1.41 mm/s per mm/s of path speed,
  // and half of a_max allows 1.25 mm/s in a cycle, less a braking step
  // (2.5 mm/s): nothing passes, every chord end is a stop, as before.
  std::vector<std::pair<double, double>> points;
  const PathRun r = run_text(equal_limits(), zigzag(10, 5.0, 90.0, 6000, points), "kink_pass_stop");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  for (const auto& [x, y] : points) ASSERT_LE(nearest(r, x, y), 1e-6) << x << " " << y;  // the trace's 6 decimals
  EXPECT_LE(largest_acceleration(r), kAMaxMmS2 + kAccelRoundingMmS2);
}

TEST(KinkPass, An8DegreeKinkPassesAtWhatHalfOfAMaxAllows) {
  // 8 degree kinks at F6000: |dt_Y| = 2 sin 4 deg = 0.1395, so at most
  // 1.25 / 0.1395 - 2.5 = 6.46 mm/s (before: a stop); the set points pass
  // each chord end within a cycle's travel at that speed, not at rest.
  std::vector<std::pair<double, double>> points;
  const PathRun r = run_text(equal_limits(), zigzag(20, 1.0, 8.0, 6000, points), "kink_pass_8deg");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  // Stopping there, the cycles on either side of the corner would be at
  // most one braking step (2.5 mm/s); passing, both run at about 6.46 mm/s
  // (up to a braking step faster).
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const std::size_t k = nearest_row(r, points[i].first, points[i].second).first;
    for (std::size_t c : {k, k + 1}) {
      EXPECT_GE(speed(r, c), 5.0) << "corner " << i;
      EXPECT_LE(speed(r, c), 6.46 + 2.5) << "corner " << i;
    }
  }
  EXPECT_LE(largest_acceleration(r), kAMaxMmS2 + kAccelRoundingMmS2);
}

TEST(KinkPass, OverrideAndFeedholdAtTheKinksKeepAMax) {
  std::vector<std::pair<double, double>> points;
  const auto dir = temp_dir("kink_pass_plc");
  std::ofstream(dir / "s.plc") << "0.5 feed_override 200\n1.0 feedhold on\n1.2 feedhold off\n1.5 feed_override 30\n"
                                  "1.9 feed_override 100\n";
  const PathRun r = run_text(equal_limits(), zigzag(300, 0.5, 1.0, 3000, points), "kink_pass_override",
                             "--plc " + (dir / "s.plc").string());
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_LE(largest_acceleration(r), kAMaxMmS2 + kAccelRoundingMmS2);
}

}  // namespace
}  // namespace nck::app::testing
