// Seeded property test of the jerk-limited slopes (issue 30) through the
// whole execution path on the mill: random programs of lines, arcs,
// reversals, feed changes, tangent line/arc pairs and polylines of short
// nearly straight blocks under #SLOPE TRAPEZ, SIN2 and HSC. Every cycle of every axis, at full precision: |v| <= vb_max,
// |a| <= a_max; inside blocks the jerk <= a/tr (TRAPEZ, HSC) or (pi/2) a/tr
// (SIN2), a and tr of the motion in force (feed: a_beschl with the
// shortest feed ramp time; G0: a_grenz with tr_grenz); within three cycles
// of a block start the transition rules hold instead (kinks change an
// axis's velocity within a_max in one cycle). No NaN, every end point
// reached, and the path passes transitions at speed (not all exact stops);
// under HSC some transitions (inside its chains) with the path still
// accelerating or braking, under TRAPEZ and SIN2 none.
// Count from NCK_PROPERTY_COUNT (default 10 per profile).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "nck/config/load.hpp"
#include "nck/kernel/kernel.hpp"
#include "nck/sim/dry_run.hpp"
#include "../seen_events.hpp"

namespace nck::kernel {
namespace {

constexpr double kDt = 0.001;
// A path acceleration above this as a block begins counts as carried on.
constexpr double kCarriedA = 500;

struct Program {
  std::string text;
  std::vector<std::array<double, 2>> points;  // programmed end points (X, Y)
};

// Lines, half circles, reversals, G0, tangent line -> arc pairs and
// polylines of short blocks turning by up to 2 degrees (HSC's chains);
// more than 30 % of the transitions turn by more than 10 degrees.
Program random_program(std::mt19937& rng, const char* slope) {
  std::uniform_real_distribution<double> pos(-40, 40), feed(600, 9000), unit(0, 1);
  std::uniform_int_distribution<int> kind(0, 9);
  Program p{fmt::format("N1 G17 G90 G0 X0 Y0 Z0\n#SLOPE [TYPE={}]\n", slope), {{0, 0}}};
  double x = 0, y = 0;
  // The point as the program text has it (formatted as there, so that the
  // rounding is the text's own).
  auto to = [&](double nx, double ny, double scale = 1000) {
    const int digits = scale == 1000 ? 3 : 4;
    p.points.push_back({std::stod(fmt::format("{:.{}f}", nx, digits)), std::stod(fmt::format("{:.{}f}", ny, digits))});
    x = p.points.back()[0], y = p.points.back()[1];
  };
  for (int i = 0; i < 30; ++i) {
    const int k = kind(rng);
    const double nx = pos(rng), ny = pos(rng);
    if (k == 9) {  // reversal
      const double bx = x, by = y;
      p.text += fmt::format("G1 X{:.3f} Y{:.3f} F{:.0f}\n", nx, ny, feed(rng));
      to(nx, ny);
      p.text += fmt::format("X{:.3f} Y{:.3f}\n", bx, by);
      to(bx, by);
    } else if (k >= 7) {  // a half circle to the new point
      const double ex = std::round(nx * 1000) / 1000, ey = std::round(ny * 1000) / 1000;
      p.text += fmt::format("G{} X{:.3f} Y{:.3f} I{:.4f} J{:.4f} F{:.0f}\n", k == 8 ? 2 : 3, ex, ey, (ex - x) / 2,
                            (ey - y) / 2, feed(rng));
      to(ex, ey);
    } else if (k == 6) {
      p.text += fmt::format("G0 X{:.3f} Y{:.3f}\n", nx, ny);
      to(nx, ny);
    } else if (k == 4) {  // polyline: short blocks at one feed, nearly straight on
      const int n = 6 + static_cast<int>(7 * unit(rng));
      const double f = feed(rng);
      double ang = 2 * std::numbers::pi * unit(rng);
      for (int s = 0; s < n; ++s) {
        ang += (unit(rng) - 0.5) * 4 * std::numbers::pi / 180;
        const double len = 0.3 + 2.7 * unit(rng);
        const double px = std::clamp(x + len * std::cos(ang), -45.0, 45.0);
        const double py = std::clamp(y + len * std::sin(ang), -45.0, 45.0);
        p.text += fmt::format("G1 X{:.4f} Y{:.4f} F{:.0f}\n", px, py, f);
        to(px, py, 10000);
      }
    } else if (k == 5) {  // tangent pair: a line, then a quarter circle leaving along it
      const double len = 5 + 20 * unit(rng), ang = 2 * std::numbers::pi * unit(rng), r = 3 + 10 * unit(rng);
      const double dx = std::cos(ang), dy = std::sin(ang);
      const double lx = std::round((x + len * dx) * 1000) / 1000, ly = std::round((y + len * dy) * 1000) / 1000;
      p.text += fmt::format("G1 X{:.3f} Y{:.3f} F{:.0f}\n", lx, ly, feed(rng));
      to(lx, ly);
      // Centre to the left (G3): the end is a quarter turn on.
      const double cx = lx - r * dy, cy = ly + r * dx;
      const double ex = cx + r * dx, ey = cy + r * dy;
      p.text += fmt::format("G3 X{:.4f} Y{:.4f} I{:.4f} J{:.4f}\n", ex, ey, cx - lx, cy - ly);
      to(ex, ey, 10000);
    } else {
      p.text += fmt::format("G1 X{:.3f} Y{:.3f} F{:.0f}\n", nx, ny, feed(rng));
      to(nx, ny);
    }
  }
  p.text += "M30\n";
  return p;
}

struct AxisBound {
  double v_max, a_max, j_feed, j_rapid;
};

// From the mill's lists: the steepest ramp each motion kind may take.
AxisBound bound(const config::AxisConfig& ax, double shape) {
  const config::GearStage& g = ax.gears.at(0);
  const double tr_feed = std::min({g.tr_acc_up_s, g.tr_acc_down_s, g.tr_dec_up_s, g.tr_dec_down_s});
  return {g.max_speed_mm_s, g.a_max, shape * std::max(g.accel_mm_s2, g.decel_mm_s2) / tr_feed,
          shape * g.rapid_accel_mm_s2 / g.tr_rapid_s};
}

void check_profile(const char* slope, double shape, std::uint32_t seed0, bool across_blocks = false) {
  const char* env = std::getenv("NCK_PROPERTY_COUNT");
  const int count = env ? std::atoi(env) : 10;
  const std::string root = NCK_SOURCE_DIR;
  config::LoadResult mill = config::load_machine(root + "/examples/mill");
  ASSERT_TRUE(mill.ok());
  std::array<AxisBound, 2> ax{bound(mill.machine->axes.at(0), shape), bound(mill.machine->axes.at(1), shape)};
  const auto dir = std::filesystem::temp_directory_path() / ("nck_slope_prop_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  int passed_at_speed = 0, transitions = 0, accelerating = 0;
  for (int n = 0; n < count; ++n) {
    std::mt19937 rng(seed0 + static_cast<std::uint32_t>(n));
    const Program prog = random_program(rng, slope);
    std::ofstream(dir / "p.nc") << prog.text;
    auto run = sim::DryRun::create(*mill.machine, {dir / "p.nc"});
    ASSERT_TRUE(run.has_value());
    auto out = std::make_unique<TickOutput>();
    std::vector<std::array<double, 2>> p;
    std::vector<bool> rapid, block_start;
    double v_before = 0;
    for (int cycle = 0; cycle < 600'000 && !run->done(); ++cycle) {
      run->step(*out);
      const ChannelOutput& ch = out->channels[0];
      ASSERT_TRUE(std::isfinite(ch.axis_mcs[0]) && std::isfinite(ch.axis_mcs[1])) << prog.text;
      p.push_back({ch.axis_mcs[0], ch.axis_mcs[1]});
      rapid.push_back(ch.cause == CycleCause::rapid);
      bool starts = false;
      for (const Event& e : out->events) {
        if (e.kind() == EventKind::block && e.channel == 1) starts = true;
        ASSERT_NE(e.kind(), EventKind::error) << number(test::diagnosis_id(e)) << " line " << e.at.line << "\n" << prog.text;
      }
      block_start.push_back(starts);
      // At speed: the path moved in the cycle before the block started.
      if (starts && v_before > 0) ++passed_at_speed;
      // The path's speed still changing as a block begins (HSC's chains).
      if (starts && v_before > 0 && std::abs(ch.path_velocity_mm_s - v_before) > kCarriedA * kDt) ++accelerating;
      v_before = ch.path_velocity_mm_s;
      transitions += starts;
    }
    ASSERT_TRUE(run->done()) << prog.text;
    const std::size_t m = p.size();
    for (std::size_t i = 3; i < m; ++i) {
      bool near_start = false;
      for (std::size_t k = i - 3; k <= i; ++k) near_start = near_start || block_start[k];
      for (std::size_t j = 0; j < 2; ++j) {
        const double v = (p[i][j] - p[i - 1][j]) / kDt, v1 = (p[i - 1][j] - p[i - 2][j]) / kDt,
                     v2 = (p[i - 2][j] - p[i - 3][j]) / kDt;
        const double a = (v - v1) / kDt, a1 = (v1 - v2) / kDt, jerk = (a - a1) / kDt;
        ASSERT_LE(std::abs(v), ax[j].v_max + 1e-6) << "axis " << j << " cycle " << i << "\n" << prog.text;
        ASSERT_LE(std::abs(a), ax[j].a_max * (1 + 1e-6) + 1e-3) << "axis " << j << " cycle " << i << "\n" << prog.text;
        if (near_start) continue;  // a transition: its own rules (kinks within a_max above)
        const double j_max = rapid[i] || rapid[i - 1] || rapid[i - 2] ? std::max(ax[j].j_rapid, ax[j].j_feed)
                                                                       : ax[j].j_feed;
        // One cycle's rounding of the set points (1e-12 mm) over dt^3.
        ASSERT_LE(std::abs(jerk), j_max * (1 + 1e-6) + 10.0) << slope << " axis " << j << " cycle " << i << "\n"
                                                              << prog.text;
      }
    }
    // Every programmed end point is passed (a set point within a cycle's travel).
    for (const auto& q : prog.points) {
      double best = 1e300;
      for (const auto& s : p) best = std::min(best, std::hypot(s[0] - q[0], s[1] - q[1]));
      ASSERT_LT(best, 0.5 * 150 * kDt + 1e-3) << q[0] << " " << q[1] << "\n" << prog.text;
    }
    ASSERT_NEAR(p.back()[0], prog.points.back()[0], 1e-6);
    ASSERT_NEAR(p.back()[1], prog.points.back()[1], 1e-6);
  }
  std::filesystem::remove_all(dir);
  // Not a run of exact stops: a good share of the block starts at speed.
  EXPECT_GT(passed_at_speed, transitions / 5) << passed_at_speed << " of " << transitions;
  // Per block the acceleration is 0 at every block end; HSC carries it on
  // inside its chains (the polylines mostly).
  if (across_blocks) {
    EXPECT_GT(accelerating, transitions / 50) << accelerating << " of " << transitions;
  } else {
    EXPECT_EQ(accelerating, 0) << transitions;
  }
}

TEST(SlopeProperty, TrapezHoldsVelocityAccelerationAndJerkEveryCycle) { check_profile("TRAPEZ", 1.0, 3000); }

TEST(SlopeProperty, Sin2HoldsVelocityAccelerationAndJerkEveryCycle) {
  check_profile("SIN2", std::numbers::pi / 2, 4000);
}

// HSC: the acceleration runs on across the transitions of its chains; the
// same bounds (trapezoidal ramps, the longest ramp times of the axes).
TEST(SlopeProperty, HscHoldsVelocityAccelerationAndJerkEveryCycle) { check_profile("HSC", 1.0, 5000, true); }

}  // namespace
}  // namespace nck::kernel
