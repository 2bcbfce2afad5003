// HSC across blocks (#SLOPE [TYPE=HSC], P-CHAN-00071 = 3) through the whole
// kernel on examples/mill (X: a_beschl = a_brems = 2500 mm/s^2, ramp times
// 50 ms, so TRAPEZ's jerk a/tr = 50,000 mm/s^3): blocks the path runs
// through at its speed form one chain planned as one move, so twenty
// collinear 1 mm blocks run exactly as one 20 mm block, the acceleration
// going on across their ends, while TRAPEZ brings it to 0 at each. A
// corner ends the chain; a chain longer than the command queue grows as
// preparation queues more.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <unistd.h>

#include "nck/config/load.hpp"
#include "nck/sim/dry_run.hpp"
#include "../seen_events.hpp"

namespace nck::kernel {
namespace {

constexpr double kDt = 0.001;

struct PathRun {
  std::vector<double> x, y;        // set points, every cycle
  std::vector<bool> block_start;   // a block began in that cycle
};

PathRun run_program(const std::string& program, const char* name) {
  const std::string root = NCK_SOURCE_DIR;
  static const config::LoadResult mill = config::load_machine(root + "/examples/mill");
  EXPECT_TRUE(mill.ok());
  const auto file = std::filesystem::temp_directory_path() / fmt::format("nck_hsc_{}_{}.nc", getpid(), name);
  std::ofstream(file) << program;
  auto created = sim::DryRun::create(*mill.machine, {file});
  EXPECT_TRUE(created.has_value());
  PathRun r;
  if (!created) return r;
  auto out = std::make_unique<TickOutput>();
  for (int cycle = 0; cycle < 200'000 && !created->done(); ++cycle) {
    created->step(*out);
    bool starts = false;
    for (const Event& e : out->events) {
      EXPECT_NE(e.kind(), EventKind::error) << number(test::diagnosis_id(e)) << " line " << e.at.line;
      starts = starts || (e.kind() == EventKind::block && e.channel == 1);
    }
    r.x.push_back(out->channels[0].axis_mcs[0]);
    r.y.push_back(out->channels[0].axis_mcs[1]);
    r.block_start.push_back(starts);
  }
  EXPECT_TRUE(created->done());
  std::filesystem::remove(file);
  return r;
}

// "#SLOPE [TYPE=..]" and then `moves`, from X0 Y0 at rest.
std::string program(const char* slope, const std::string& moves) {
  return fmt::format("N1 G17 G90 G0 X0 Y0 Z0\n#SLOPE [TYPE={}]\n{}M30\n", slope, moves);
}

std::string collinear(int blocks, double step_mm, int feed) {
  std::string s;
  for (int i = 1; i <= blocks; ++i) s += fmt::format("G1 X{:.3f} F{}\n", i * step_mm, feed);
  return s;
}

// The first cycle in which the path has left X0 (the G1s start).
std::size_t departure(const PathRun& r) {
  for (std::size_t i = 0; i < r.x.size(); ++i)
    if (r.x[i] > 1e-12) return i;
  return r.x.size();
}

// The cycle in which X first reaches `x` (the end of the motion).
std::size_t arrival(const PathRun& r, double x) {
  for (std::size_t i = 0; i < r.x.size(); ++i)
    if (std::abs(r.x[i] - x) < 1e-9) return i;
  return r.x.size();
}

double accel_at(const std::vector<double>& p, std::size_t i) {
  return (p[i] - 2 * p[i - 1] + p[i - 2]) / (kDt * kDt);
}

double max_jerk(const std::vector<double>& p) {
  double m = 0;
  for (std::size_t i = 3; i < p.size(); ++i)
    m = std::max(m, std::abs(p[i] - 3 * p[i - 1] + 3 * p[i - 2] - p[i - 3]) / (kDt * kDt * kDt));
  return m;
}

TEST(HscChain, CollinearBlocksRunAsOneBlock) {
  const PathRun one = run_program(program("HSC", "G1 X20 F12000\n"), "one");
  const PathRun chain = run_program(program("HSC", collinear(20, 1.0, 12000)), "chain");
  const PathRun trapez = run_program(program("TRAPEZ", collinear(20, 1.0, 12000)), "trapez");
  const std::size_t t_one = arrival(one, 20), t_chain = arrival(chain, 20), t_trapez = arrival(trapez, 20);
  ASSERT_LT(t_one, one.x.size());
  EXPECT_LE(t_chain, t_one + 1);
  EXPECT_GE(t_chain + 1, t_one);
  // The same set points, cycle by cycle (the replans at the block ends
  // continue the plan exactly).
  const std::size_t from = departure(one);
  ASSERT_EQ(departure(chain), from);
  for (std::size_t i = from; i < std::min(t_one, t_chain); ++i) ASSERT_NEAR(chain.x[i], one.x[i], 1e-6) << i;
  // Per block (TRAPEZ) the acceleration returns to 0 at every block end.
  EXPECT_GT(t_trapez - from, (t_chain - from) * 3 / 2);
  EXPECT_LE(max_jerk(chain.x), 50'000 * (1 + 1e-6) + 10.0);
}

TEST(HscChain, AccelerationGoesOnAcrossTheBlockEnds) {
  const PathRun chain = run_program(program("HSC", collinear(20, 1.0, 12000)), "across");
  const PathRun trapez = run_program(program("TRAPEZ", collinear(20, 1.0, 12000)), "per-block");
  // |a| where a block of the chain starts (not the first and the last).
  auto at_starts = [](const PathRun& r) {
    std::vector<double> a;
    for (std::size_t i = 2; i < r.x.size(); ++i)
      if (r.block_start[i] && r.x[i - 1] > 0.5 && r.x[i] < 19.5) a.push_back(std::abs(accel_at(r.x, i)));
    return a;
  };
  const auto hsc = at_starts(chain), per_block = at_starts(trapez);
  ASSERT_GE(hsc.size(), 15u);
  EXPECT_GT(*std::max_element(hsc.begin(), hsc.end()), 2000);  // near a_beschl 2500 at a transition
  // TRAPEZ passes each transition with the acceleration back near 0 (one
  // cycle's sample of a ramp of 50,000 mm/s^3: at most 50 mm/s^2 or so).
  ASSERT_FALSE(per_block.empty());
  EXPECT_LT(*std::max_element(per_block.begin(), per_block.end()), 100);
}

TEST(HscChain, ACornerEndsTheChain) {
  // X then Y: a right angle, passed at the corner's speed (the kink rule)
  // with the acceleration 0 there, as per block.
  const PathRun hsc = run_program(program("HSC", "G1 X10 F6000\nG1 X10 Y10\n"), "corner");
  const PathRun trapez = run_program(program("TRAPEZ", "G1 X10 F6000\nG1 X10 Y10\n"), "corner-trapez");
  EXPECT_EQ(hsc.x, trapez.x);
  EXPECT_EQ(hsc.y, trapez.y);
}

// More blocks than the command queue (128) and the look-ahead window (120)
// hold: the chain reaches the end of the queue, so its end is a stop until
// preparation queues more, and it grows as it does. At F6000 (100 mm/s)
// over 300 blocks of 0.5 mm the path runs as one 150 mm move would.
TEST(HscChain, ALongChainGrowsWithTheQueue) {
  const PathRun one = run_program(program("HSC", "G1 X150 F6000\n"), "long-one");
  const PathRun chain = run_program(program("HSC", collinear(300, 0.5, 6000)), "long-chain");
  const std::size_t t_one = arrival(one, 150), t_chain = arrival(chain, 150);
  ASSERT_LT(t_one, one.x.size());
  EXPECT_LE(t_chain, t_one + 2);
  EXPECT_LE(max_jerk(chain.x), 50'000 * (1 + 1e-6) + 10.0);
}

}  // namespace
}  // namespace nck::kernel
