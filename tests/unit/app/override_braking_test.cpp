// Braking for a lower target under a jerk-limited slope (issue 44, item 1,
// found by tests/motion/limits_property.py, with --jerk for the last test): an override step to 0 on an
// arc that already brakes for the kink at its end passes the kink no faster
// than planned. A new plan from the braking state could only meet the end
// speed past the end, and passed the kink at 19.5 mm/s instead of its
// corner speed: Y jumped by 4,212 mm/s^2 (a_max 3,000). The same when the
// target rises again (a stop released at once).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "spindle_path_helpers.hpp"

namespace nck::app::testing {
namespace {

void expect_within_a_max(const PathRun& r) {
  const double a_max[] = {3000, 3000, 2500};
  const char* axes[] = {"X", "Y", "Z"};
  for (std::size_t i = 2; i < r.rows.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double a = (r.rows[i].at(axes[k]) - 2 * r.rows[i - 1].at(axes[k]) + r.rows[i - 2].at(axes[k])) / (kDt * kDt);
      ASSERT_LE(std::abs(a), a_max[k] + 3.0) << axes[k] << " at " << r.rows[i].at("t");  // + the trace's digits
    }
}

TEST(OverrideBraking, OverrideZeroBeforeAKinkKeepsTheAxesWithinAMax) {
  const auto plc = temp_dir("ovr_kink_plc") / "s.plc";
  write(plc, "0.30 feed_override 0\n");  // as the arc starts braking for the kink
  const PathRun r = run_text("mill",
                             "N1 G90 G17 F20000\n#SLOPE [TYPE=SIN2]\n#CONTOUR MODE [DEV PATH_DEV=0.05]\nG261\n"
                             "G3 X-1.4397 Y-36.3712 I10.712 J-18.6381\nG1 X25.762 Y-41.499 Z10\nM30\n",
                             "ovr_kink", "--plc " + plc.string() + " --max-time 2");
  ASSERT_EQ(r.cli.exit_code, 1) << r.cli.output;  // --max-time: the override holds the path
  ASSERT_GT(r.rows.size(), 1000u);
  expect_within_a_max(r);
  // The arc's end was passed and the path stands in the line after it.
  EXPECT_GT(r.line_t(6), 0.5);
  EXPECT_DOUBLE_EQ(r.rows.back().at("X"), r.rows[r.rows.size() - 2].at("X"));
}

// An NC stop released in the next cycle (auto cycle start) on an arc that
// "just fits" its braking to the fillet at its end: the plan from the
// state one cycle later could only meet the end past it, and passed the
// fillet at 9 mm/s instead of 0.08 (X jumped by 8,956 mm/s^2). The plan in
// force stays until the arc's end.
TEST(OverrideBraking, AStopReleasedAtOnceKeepsTheFilletSpeed) {
  const auto plc = temp_dir("stop_kink_plc") / "s.plc";
  write(plc, "0.698 stop\n");
  const PathRun r = run_text("mill",
                             "N1 G90 G17 F3000\n#SLOPE [TYPE=SIN2]\n#CONTOUR MODE [DEV PATH_DEV=0.05]\nG261\n"
                             "G1 X9.634 Y-16.224 Z4.52\nG1 X9.458 Y-16.709 Z4.933\nG3 X17.1288 Y-13.5499 I1.088 J8.2507\n"
                             "G1 X16.545 Y-13.684 Z5.218\nG0 X60.439 Y-31.516 Z7.576\nM30\n",
                             "stop_kink", "--plc " + plc.string());
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  expect_within_a_max(r);
}

// The largest |third difference| of X over the rows before t_end_s.
double largest_x_jerk(const PathRun& r, double t_end_s) {
  double worst = 0;
  for (std::size_t i = 3; i < r.rows.size() && r.rows[i].at("t") < t_end_s; ++i) {
    const auto x = [&](std::size_t k) { return r.rows[k].at("X"); };
    worst = std::max(worst, std::abs((x(i) - 3 * x(i - 1) + 3 * x(i - 2) - x(i - 3)) / (kDt * kDt * kDt)));
  }
  return worst;
}

// An NC stop released at once while a SIN2 G0 that brakes to a standstill
// at its end ramps its acceleration down: a stop from there could only fit
// with ramps shorter than tr_grenz (a new sin^2 ramp starts at jerk 0 where
// the one under way is at its peak), so X reached 516,000 mm/s^3 against
// the drive's pi/2 a_max / tr_min = 471,239. The plan in force stays.
TEST(OverrideBraking, AStopReleasedAtOnceInASin2RampKeepsTheJerk) {
  const auto plc = temp_dir("stop_sin2_plc") / "s.plc";
  write(plc, "0.272 stop\n0.377 feedhold on\n0.737 feedhold off\n");
  const PathRun r = run_text("mill",
                             "N1 G90 G17 F20000\n#SLOPE [TYPE=SIN2]\nG1 X-0.144 Y0.571 Z0.654\n"
                             "G1 X-0.225 Y0.581 Z0.812\nG0 X59.825 Y15.452 Z-21.503\nG1 X59.759 Y15.252 Z-21.353\nM30\n",
                             "stop_sin2", "--plc " + plc.string());
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  expect_within_a_max(r);
  const double bound = std::numbers::pi / 2 * 3000 / 0.010;  // X: a_max 3,000, tr_min 10 ms
  EXPECT_LE(largest_x_jerk(r, r.of("end").at(0)["t"].get<double>()), bound + 4000);  // + the trace's digits
}

}  // namespace
}  // namespace nck::app::testing
