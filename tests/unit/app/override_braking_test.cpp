// Braking for a lower target under a jerk-limited slope (issue 44, item 1,
// found by tests/motion/limits_property.py): an override step to 0 on an
// arc that already brakes for the kink at its end passes the kink no faster
// than planned. A new plan from the braking state could only meet the end
// speed past the end, and passed the kink at 19.5 mm/s instead of its
// corner speed: Y jumped by 4,212 mm/s^2 (a_max 3,000). The same when the
// target rises again (a stop released at once).
#include <gtest/gtest.h>

#include <cmath>

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
  write(plc, "0.386 feed_override 0\n");
  const PathRun r = run_text("mill",
                             "N1 G90 G17 F20000\n#SLOPE [TYPE=SIN2]\n#CONTOUR MODE [DEV PATH_DEV=0.05]\nG261\n"
                             "G3 X-1.4397 Y-36.3712 I10.712 J-18.6381\nG1 X25.762 Y-41.499 Z10\nM30\n",
                             "ovr_kink", "--plc " + plc.string() + " --max-time 2");
  ASSERT_EQ(r.cli.exit_code, 1) << r.cli.output;  // --max-time: the override holds the path
  ASSERT_GT(r.rows.size(), 1000u);
  expect_within_a_max(r);
  // The arc's end was passed and the path stands in the line after it.
  EXPECT_GT(r.line_t(6), 0.6);
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

}  // namespace
}  // namespace nck::app::testing
