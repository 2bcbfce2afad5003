// Continuous path through `nck run` (issue 12): the path keeps its speed
// through tangent transitions, stops exactly where G60/G360 ask, and no
// axis ever exceeds its velocity or acceleration (mill: max_speed_mm_s 500 mm/s,
// a_max X/Y 3000, Z 2500 mm/s^2, 1 ms cycle).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <random>

#include <fmt/format.h>

#include "cli_helpers.hpp"
#include "nck/config/load.hpp"
#include "nck/sim/dry_run.hpp"

namespace nck::app {
namespace {

using namespace testing;
using nlohmann::json;

constexpr double kDt = 0.001;

struct Trace {
  std::vector<double> t;
  std::vector<std::array<double, 3>> p;  // X Y Z
};

Trace read_trace(const std::filesystem::path& f) {
  Trace tr;
  const auto lines = split(read_file(f), '\n');
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto c = split(lines[i], ',');
    if (c.size() < 4) continue;
    tr.t.push_back(std::stod(c[0]));
    tr.p.push_back({std::stod(c[1]), std::stod(c[2]), std::stod(c[3])});
  }
  return tr;
}

// Path speed over the cycle ending at row i.
double speed(const Trace& tr, std::size_t i) {
  if (i == 0) return 0;
  double d2 = 0;
  for (int k = 0; k < 3; ++k) d2 += std::pow(tr.p[i][k] - tr.p[i - 1][k], 2);
  return std::sqrt(d2) / kDt;
}

// Row of the cycle at time t.
std::size_t row_at(const Trace& tr, double t) {
  return static_cast<std::size_t>(std::lower_bound(tr.t.begin(), tr.t.end(), t - 1e-9) - tr.t.begin());
}

struct PathRun {
  CliResult cli;
  Trace trace;
  std::map<long, double> block_t;  // N -> start
  double end_t = 0;
};

// Runs a program file on the mill with trace, events and final state.
PathRun run_mill_file(const std::filesystem::path& program, const std::filesystem::path& dir,
                      const std::string& options = "") {
  PathRun r;
  r.cli = run_nck("run " + root() + "/examples/mill " + program.string() + options + " --trace " + (dir / "t.csv").string() +
                  " --events " + (dir / "e.jsonl").string() + " --final " + (dir / "f.json").string());
  r.trace = read_trace(dir / "t.csv");
  for (const json& e : read_jsonl(dir / "e.jsonl"))
    if (e["ev"] == "block" && !e["n"].is_null()) r.block_t[e["n"].get<long>()] = e["t"];
  r.end_t = json::parse(read_file(dir / "f.json"))["time"];
  return r;
}

PathRun run_mill(const std::string& name, const std::string& program) {
  const auto dir = temp_dir(name);
  std::ofstream(dir / "p.nc") << program;
  return run_mill_file(dir / "p.nc", dir);
}

TEST(ContinuousPath, ContourKeepsItsSpeedThroughTangentTransitions) {
  const PathRun r = run_mill_file(root() + "/examples/mill/contour.nc", temp_dir("cp-contour"));
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  // The pocket N80..N150 at F1200 (20 mm/s): lines and corner arcs meet
  // tangentially, so every transition is passed at the feed.
  for (long n : {90, 100, 110, 120, 130, 140, 150}) {
    const std::size_t i = row_at(r.trace, r.block_t.at(n));
    EXPECT_NEAR(speed(r.trace, i), 20.0, 0.05) << "N" << n;
    EXPECT_NEAR(speed(r.trace, i + 1), 20.0, 0.05) << "N" << n;
  }
}

TEST(ContinuousPath, BlendingShortensTheCycleTimeOverExactStop) {
  const std::string pocket = "N10 G1 X32 Y-25 F1200\nN20 X-32\nN30 G2 X-40 Y-17 I0 J8\nN40 G1 Y17\nN50 G2 X-32 Y25 I8 J0\n"
                             "N60 G1 X32\nN70 M30\n";
  PathRun blend = run_mill("cp-blend", "N5 G0 X32 Y-25\n" + pocket);
  PathRun exact = run_mill("cp-exact", "N5 G0 X32 Y-25\nN6 G360\n" + pocket);
  ASSERT_EQ(blend.cli.exit_code, 0) << blend.cli.output;
  ASSERT_EQ(exact.cli.exit_code, 0) << exact.cli.output;
  const double feed_time = (64 + 64 + 34 + 2 * (M_PI * 8 / 2)) / 20.0;  // length / 20 mm/s
  const double blend_s = blend.end_t - blend.block_t.at(10), exact_s = exact.end_t - exact.block_t.at(10);
  EXPECT_LT(blend_s, exact_s - 0.02);  // four transitions, each ~8 ms of ramp at 2500 mm/s^2
  EXPECT_LT(blend_s, feed_time * 1.01 + 0.05);
}

TEST(ContinuousPath, G60AndG360StopExactlyAndG359Blends) {
  // At an exact stop the last cycle of one block and the first of the next
  // move at most one braking / accelerating step (2500 mm/s^2 * 1 ms).
  auto stops_at = [](const PathRun& r, long n) {
    const std::size_t i = row_at(r.trace, r.block_t.at(n));
    return speed(r.trace, i) < 3.0 && speed(r.trace, i - 1) < 3.0;
  };
  PathRun g60 = run_mill("cp-g60", "N10 G1 X10 F1200\nN20 G60 X20\nN30 X30\nN40 X40\nN50 M30\n");
  ASSERT_EQ(g60.cli.exit_code, 0) << g60.cli.output;
  EXPECT_FALSE(stops_at(g60, 20));  // N10 -> N20 blends
  EXPECT_TRUE(stops_at(g60, 30));   // G60: N20 ends at standstill
  EXPECT_FALSE(stops_at(g60, 40));  // non-modal
  PathRun g360 = run_mill("cp-g360", "N10 G360 G1 X10 F1200\nN20 X20\nN30 G359 X30\nN40 X40\nN50 M30\n");
  ASSERT_EQ(g360.cli.exit_code, 0) << g360.cli.output;
  EXPECT_TRUE(stops_at(g360, 20));
  EXPECT_TRUE(stops_at(g360, 30));
  EXPECT_FALSE(stops_at(g360, 40));
}

// A reversal stops exactly; the first step back takes what is left of
// a_max after the last step into the stop: (3000 - 2500) mm/s^2 x 1 ms =
// 0.5 mm/s, with no cycle standing still between them.
TEST(ContinuousPath, ReversalStartsGentlyOutOfTheStop) {
  PathRun r = run_mill("cp-reversal", "N10 G1 X10 F1200\nN20 X0\nN30 M30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const std::size_t i = row_at(r.trace, r.block_t.at(20));
  const double v_last = (r.trace.p[i - 1][0] - r.trace.p[i - 2][0]) / kDt;
  const double v_first = (r.trace.p[i][0] - r.trace.p[i - 1][0]) / kDt;
  EXPECT_GT(v_last, 0.0);
  EXPECT_LE(v_last, 2.5 + 1e-3);
  EXPECT_NEAR(v_first, -0.5, 1e-3);
  EXPECT_LE((v_last - v_first) / kDt, 3000 + 2.0);
}

TEST(ContinuousPath, G60WithoutMotionIsError20003) {
  PathRun r = run_mill("cp-g60-bad", "N10 G1 X10 F1200\nN20 G60\nN30 M30\n");
  EXPECT_EQ(r.cli.exit_code, 1) << r.cli.output;
  EXPECT_NE(r.cli.output.find("20003"), std::string::npos) << r.cli.output;
}

// Per-axis limits hold on random programs (seeded; NCK_PROPERTY_COUNT sets
// how many): lines, arcs, feed changes and reversals.
struct RandomProgram {
  std::string text;
  std::vector<std::array<double, 3>> points;  // every programmed end point
  double length_mm = 0;                       // of the programmed path
};

RandomProgram random_program(std::mt19937& rng) {
  std::uniform_real_distribution<double> pos(-40, 40), small(-0.5, 0.5), feed(300, 6000), zpos(-5, 5);
  std::uniform_int_distribution<int> kind(0, 9);
  RandomProgram p{"N1 G17 G90 G0 X0 Y0 Z0\n", {{0, 0, 0}}};
  double x = 0, y = 0, z = 0;
  auto line = [&](int g, double nx, double ny, double nz, double f) {
    p.text += g == 0 ? fmt::format("G0 X{:.3f} Y{:.3f} Z{:.3f}\n", nx, ny, nz)
                     : fmt::format("G1 X{:.3f} Y{:.3f} F{:.0f}\n", nx, ny, f);
    const auto from = p.points.back();
    p.points.push_back({std::round(nx * 1000) / 1000, std::round(ny * 1000) / 1000, std::round(nz * 1000) / 1000});
    const auto& q = p.points.back();
    p.length_mm += std::hypot(q[0] - from[0], q[1] - from[1], q[2] - from[2]);
  };
  for (int i = 0; i < 40; ++i) {
    const int k = kind(rng);
    const bool near = k < 3;
    const double nx = near ? x + small(rng) : pos(rng), ny = near ? y + small(rng) : pos(rng);
    if (k == 9) {  // reversal: there and back
      line(1, nx, ny, z, feed(rng));
      line(1, x, y, z, feed(rng));
      continue;
    }
    if (k == 8 || k == 7) {  // a half circle to the new point
      const double ex = std::round(nx * 1000) / 1000, ey = std::round(ny * 1000) / 1000;
      p.text += fmt::format("G{} X{:.3f} Y{:.3f} I{:.4f} J{:.4f} F{:.0f}\n", k == 8 ? 2 : 3, ex, ey, (ex - x) / 2,
                            (ey - y) / 2, feed(rng));
      p.points.push_back({ex, ey, z});
      p.length_mm += M_PI / 2 * std::hypot(ex - x, ey - y);
    } else if (k == 6) {
      z = zpos(rng);
      line(0, nx, ny, z, 0);
    } else {
      line(1, nx, ny, z, feed(rng));
    }
    x = p.points.back()[0], y = p.points.back()[1], z = p.points.back()[2];
  }
  p.text += "M30\n";
  return p;
}

// Distance from q to the trace's polyline (the path between cycles).
double distance_to_trace(const Trace& tr, const std::array<double, 3>& q) {
  double best = 1e300;
  for (std::size_t i = 1; i < tr.p.size(); ++i) {
    std::array<double, 3> d{}, w{};
    double dd = 0, t = 0;
    for (int k = 0; k < 3; ++k) d[k] = tr.p[i][k] - tr.p[i - 1][k], w[k] = q[k] - tr.p[i - 1][k], dd += d[k] * d[k];
    if (dd > 0) for (int k = 0; k < 3; ++k) t += w[k] * d[k] / dd;
    t = std::clamp(t, 0.0, 1.0);
    double e = 0;
    for (int k = 0; k < 3; ++k) e += std::pow(w[k] - t * d[k], 2);
    best = std::min(best, std::sqrt(e));
  }
  return best;
}

// The blends preparation placed in a program on the mill (fillets and
// parabolas), from a dry run of it.
prep::BlendStats blends_of(const std::string& text) {
  const auto file = temp_dir("cp-prop-blends") / "p.nc";
  std::ofstream(file) << text;
  static const config::Machine mill = *config::load_machine(root() + "/examples/mill").machine;
  auto run = sim::DryRun::create(mill, {file});
  if (!run) return {};
  auto out = std::make_unique<kernel::TickOutput>();
  while (!run->done()) run->step(*out);
  return run->prep(0).blend_stats();
}

// Runs `count` random programs (with `prelude` after the first block) and
// checks every cycle: no axis beyond max_speed_mm_s or a_max, every programmed end
// point within end_tol_mm of the trace, and the trace no shorter than the
// programmed path minus max_short_per_block_mm per block.
void check_random_programs(const std::string& prelude, double end_tol_mm, double max_short_per_block_mm) {
  const char* env = std::getenv("NCK_PROPERTY_COUNT");
  const int count = env ? std::atoi(env) : 12;
  const std::array<double, 3> v_max{500, 500, 500}, a_max{3000, 3000, 2500};
  std::mt19937 rng(20261123);
  prep::BlendStats blends{};  // of the first 12 programs: both kinds of blend are among what is checked
  for (int n = 0; n < count; ++n) {
    RandomProgram program = random_program(rng);
    program.text.insert(program.text.find('\n') + 1, prelude);
    if (!prelude.empty() && n < 12) {
      const prep::BlendStats b = blends_of(program.text);
      blends.blends += b.blends;
      blends.parabolas += b.parabolas;
    }
    PathRun r = run_mill("cp-prop", program.text);
    std::ofstream(temp_dir("cp-prop-last") / "p.nc") << program.text;
    ASSERT_EQ(r.cli.exit_code, 0) << program.text << r.cli.output;
    const Trace& tr = r.trace;
    double travelled_mm = 0;
    for (std::size_t i = 1; i < tr.p.size(); ++i)
      travelled_mm += std::hypot(tr.p[i][0] - tr.p[i - 1][0], tr.p[i][1] - tr.p[i - 1][1], tr.p[i][2] - tr.p[i - 1][2]);
    for (std::size_t i = 2; i < tr.p.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const double v1 = (tr.p[i][k] - tr.p[i - 1][k]) / kDt, v0 = (tr.p[i - 1][k] - tr.p[i - 2][k]) / kDt;
        ASSERT_LE(std::fabs(v1), v_max[k] + 0.01) << "axis " << k << " t " << tr.t[i] << "\n" << program.text;
        // 1e-6 mm trace resolution: +-2 mm/s^2 of rounding in a second difference.
        ASSERT_LE(std::fabs(v1 - v0) / kDt, a_max[k] + 5.0) << "axis " << k << " t " << tr.t[i] << "\n" << program.text;
      }
    // The set points are on the programmed path; between two cycles the
    // trace's straight chord cuts a kink by at most a few micrometres (one
    // cycle's travel at the corner speed times the kink's half angle).
    for (const auto& q : program.points)
      ASSERT_LT(distance_to_trace(tr, q), end_tol_mm) << q[0] << " " << q[1] << " " << q[2] << "\n" << program.text;
    // Chords of the trace are never longer than the path; blends may cut.
    // Rounding of the trace (1e-6 mm) adds up to ~2e-6 mm per cycle.
    const double blocks = static_cast<double>(program.points.size()), rounding = 2e-6 * static_cast<double>(tr.p.size());
    EXPECT_GE(travelled_mm, program.length_mm - max_short_per_block_mm * blocks - rounding) << program.text;
    EXPECT_LE(travelled_mm, program.length_mm + rounding) << program.text;
  }
  if (!prelude.empty() && count >= 12) {
    EXPECT_GT(blends.parabolas, 0u);
    EXPECT_GT(blends.blends, blends.parabolas);  // fillets too
  }
}

TEST(ContinuousPathProperty, NoAxisExceedsItsLimitsAndEveryEndPointIsOnThePath) {
  check_random_programs("", 0.01, 0.0005);
}

// The same with corner blending on (G261, PATH_DEV 0.05 mm): every
// programmed corner within PATH_DEV of the trace (+2 um for the trace's
// chords), and the trace at most 2 x PATH_DEV shorter per corner (a fillet
// of deviation d at a turn phi cuts 2 r tan(phi/2) - r phi, which is below
// 2 d for every phi < 180 degrees, r = d / (1/cos(phi/2) - 1)).
TEST(ContinuousPathProperty, BlendedCornersStayWithinPathDevAndLimits) {
  check_random_programs("#CONTOUR MODE [DEV PATH_DEV=0.05]\nG261\n", 0.05 + 0.002, 2 * 0.05);
}

// The same at issue 30's PATH_DEV 0.01 mm: small fillets, run at their
// centripetal limit, passed into and out of within one cycle.
TEST(ContinuousPathProperty, BlendedCornersStayWithinPathDev001AndLimits) {
  check_random_programs("#CONTOUR MODE [DEV PATH_DEV=0.01]\nG261\n", 0.01 + 0.002, 2 * 0.01);
}

// examples/mill/contour_blend.nc: a 20 mm square at F1200 (20 mm/s) with
// G261, PATH_DEV 0.05. At a right angle the fillet's radius is
// r = 0.05 / (sqrt(2) - 1) = 0.12071 mm; a fillet gives speeding up on it
// 25 % of the plane axes' feed acceleration (625 mm/s^2) and the turn what
// that leaves of 99 % of their a_max (3000 mm/s^2):
// sqrt(2970^2 - 625^2) = 2903 mm/s^2, so its speed limit is
// sqrt(2903 * r) = 18.72 mm/s (before issue 30: 96.8 % of the feed
// acceleration, 17.09 mm/s).
TEST(CornerBlending, ExampleRunsThroughTheCornersWithinPathDev) {
  const PathRun blend = run_mill_file(root() + "/examples/mill/contour_blend.nc", temp_dir("cb-example"));
  ASSERT_EQ(blend.cli.exit_code, 0) << blend.cli.output;
  std::string sharp_text = read_file(root() + "/examples/mill/contour_blend.nc");
  sharp_text.replace(sharp_text.find("N50 G261"), 8, "N50 G260");
  const PathRun sharp = run_mill("cb-sharp", sharp_text);
  ASSERT_EQ(sharp.cli.exit_code, 0) << sharp.cli.output;
  const double r = 0.05 / (std::sqrt(2.0) - 1), a_turn = std::sqrt(2970.0 * 2970.0 - 625.0 * 625.0);
  const double v_fillet = std::sqrt(a_turn * r);
  EXPECT_NEAR(v_fillet, 18.72, 0.01);
  // No stop from the start of N60 to the end of N80 (three corners); the
  // slowest cycle runs through the fillet at its limit (the passing cycle
  // keeps the planned speed exactly; a chord of 0.14 rad of the fillet is
  // 0.08 % shorter than its arc).
  const std::size_t i0 = row_at(blend.trace, blend.block_t.at(60)), i1 = row_at(blend.trace, blend.block_t.at(90));
  double v_min = 1e9;
  for (std::size_t i = i0; i < i1; ++i) v_min = std::min(v_min, speed(blend.trace, i));
  EXPECT_NEAR(v_min, v_fillet * 0.9992, 0.01);
  // The corner (20, 0) is PATH_DEV from the trace, not closer, not farther.
  EXPECT_NEAR(distance_to_trace(blend.trace, {20, 0, -1}), 0.05, 0.002);
  EXPECT_NEAR(distance_to_trace(blend.trace, {20, 20, -1}), 0.05, 0.002);
  // N80 -> N90 (G260 acts after N90): the start X0 Y0 lies on the trace
  // too, so only the cycles from N80 on count.
  Trace late;
  for (std::size_t i = row_at(blend.trace, blend.block_t.at(80)); i < blend.trace.p.size(); ++i)
    late.t.push_back(blend.trace.t[i]), late.p.push_back(blend.trace.p[i]);
  EXPECT_NEAR(distance_to_trace(late, {0, 0, -1}), 0.05, 0.002);
  // Without blending every corner slows to 0.5 mm/s (about v / a = 8 ms
  // lost with the two ramps); a fillet costs about (20 - 18.7)^2 / (2500 * 20) = 0.03 ms.
  EXPECT_LT(blend.end_t, sharp.end_t - 4 * 0.004);
  EXPECT_LT(distance_to_trace(sharp.trace, {20, 0, -1}), 0.002);
}

// Issue 30: the common program's right angle between a chord and a small
// semicircle (r 0.25 mm), here twice (into and out of it), at PATH_DEV
// 0.01 mm. The fillets (r ~ 0.026 mm) turn with what 25 % of the feed
// acceleration leaves of 99 % of a_max, the semicircle speeds up and brakes
// with what its turn leaves of a_max, and the blocks pass into and out of
// the fillets without a cycle held at the fillet's speed. Before issue 30
// the slowest cycle ran at sqrt(0.968 * 2500 * 0.026) = 7.9 mm/s; now at
// 8.5 mm/s or more. Every cycle within each axis's vb_max and a_max, both
// corners within PATH_DEV of the trace (+2 um for its chords).
TEST(CornerBlending, RightAnglesAtASmallSemicircleWithinPathDev001) {
  const PathRun r = run_mill("cb-semicircle",
                             "N10 G17 G90 G0 X0 Y0 Z-1\n#CONTOUR MODE [DEV PATH_DEV=0.01]\nG261\n"
                             "N20 G1 X2 Y0 F1500\nN30 G2 X2.5 Y0 I0.25 J0 F1200\nN40 G1 X4.5 Y0 F1500\n"
                             "N50 G1 X4.5 Y2\nM30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const Trace& tr = r.trace;
  const std::array<double, 3> a_max{3000, 3000, 2500};
  for (std::size_t i = 2; i < tr.p.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double v1 = (tr.p[i][k] - tr.p[i - 1][k]) / kDt, v0 = (tr.p[i - 1][k] - tr.p[i - 2][k]) / kDt;
      ASSERT_LE(std::fabs(v1), 500.01) << "axis " << k << " t " << tr.t[i];
      ASSERT_LE(std::fabs(v1 - v0) / kDt, a_max[k] + 5.0) << "axis " << k << " t " << tr.t[i];
    }
  // From N20's last 0.2 mm (8 ms at F1500) to N40's first: both fillets.
  const std::size_t i0 = row_at(tr, r.block_t.at(30) - 0.008), i1 = row_at(tr, r.block_t.at(40) + 0.008);
  double v_min = 1e9;
  for (std::size_t i = i0; i < i1; ++i) v_min = std::min(v_min, speed(tr, i));
  EXPECT_GE(v_min, 8.5);
  EXPECT_LT(distance_to_trace(tr, {2, 0, -1}), 0.01 + 0.002);
  EXPECT_LT(distance_to_trace(tr, {2.5, 0, -1}), 0.01 + 0.002);
}

// Issue 30's parabolic blend (STEP): a right angle between lines along the
// axes at PATH_DEV 0.01 mm. Legs L = 0.04 / sqrt 2 mm, the path enters at
// v = sqrt(2 L (0.99 a_max - 0.05 a)) = 12.686 mm/s (a fillet: 8.37), and
// inside X brakes and Y speeds up, each by v^2 / (2 L) = 2845 mm/s^2 in
// every cycle; the true speed dips to v cos 45 degrees in the middle.
TEST(CornerBlending, ParabolaAtARightAngleMatchesTheClosedForm) {
  const PathRun r = run_mill("cb-parabola",
                             "N10 G17 G90 G0 X0 Y0 Z-1\n#CONTOUR MODE [DEV PATH_DEV=0.01]\nG261\n"
                             "N20 G1 X5 Y0 F1500\nN30 G1 X5 Y5\nM30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  const Trace& tr = r.trace;
  const double leg = 0.04 / std::sqrt(2.0), v = std::sqrt(2 * leg * (0.99 * 3000 - 0.05 * 2500));
  const double a_turn = v * v / (2 * leg);
  auto inside = [&](std::size_t i) { return tr.p[i][0] > 5 - leg + 1e-6 && tr.p[i][1] < leg - 1e-6; };
  std::size_t cycles_inside = 0, last_before = 0;
  double v_min = 1e9;
  for (std::size_t i = 2; i < tr.p.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double v1 = (tr.p[i][k] - tr.p[i - 1][k]) / kDt, v0 = (tr.p[i - 1][k] - tr.p[i - 2][k]) / kDt;
      ASSERT_LE(std::fabs(v1), 500.01) << "axis " << k << " t " << tr.t[i];
      ASSERT_LE(std::fabs(v1 - v0) / kDt, (k == 2 ? 2500 : 3000) + 5.0) << "axis " << k << " t " << tr.t[i];
    }
    if (tr.p[i][0] <= 5 - leg && tr.p[i][1] == 0) last_before = i;
    if (!(inside(i - 2) && inside(i - 1) && inside(i))) continue;
    ++cycles_inside;
    const double ax = (tr.p[i][0] - 2 * tr.p[i - 1][0] + tr.p[i - 2][0]) / (kDt * kDt);
    const double ay = (tr.p[i][1] - 2 * tr.p[i - 1][1] + tr.p[i - 2][1]) / (kDt * kDt);
    EXPECT_NEAR(ax, -a_turn, 5.0) << tr.t[i];
    EXPECT_NEAR(ay, a_turn, 5.0) << tr.t[i];
    v_min = std::min(v_min, speed(tr, i));
  }
  EXPECT_NEAR(v, 12.686, 0.001);
  EXPECT_GE(cycles_inside, 1u);  // 4.5 cycles long: at least one second difference wholly inside
  EXPECT_NEAR(speed(tr, last_before), v, 0.01);  // entered at its limit
  EXPECT_GT(v_min, v * std::sqrt(0.5) - 0.05);
  EXPECT_NEAR(distance_to_trace(tr, {5, 0, -1}), 0.01, 0.002);
}

// The operator on a parabola: a feedhold (brakes along it with 5 % of the
// feed acceleration, the rest after it) or an override change starting in
// any cycle around the chord/semicircle right angles keeps every axis
// within a_max.
TEST(CornerBlending, FeedholdAndOverrideOnAParabolaKeepTheAxesWithinAMax) {
  const auto dir = temp_dir("cb-parabola-hold");
  std::ofstream(dir / "p.nc") << "N10 G17 G90 G0 X0 Y0 Z-1\n#CONTOUR MODE [DEV PATH_DEV=0.01]\nG261\n"
                                 "N20 G1 X5 Y0 F1500\nN30 G2 X5.5 Y0 I0.25 J0 F1200\nN40 G1 X5.5 Y-5 F1500\nM30\n";
  // N30 starts at 0.248 s, N40 at 0.287 s: the parabolas lie around both.
  // The feedhold is released 0.1 s later (a held program would run on to the run's time limit).
  for (const char* action : {"feedhold on", "feed_override 10", "feed_override 150"})
    for (int ms = 238; ms <= 296; ms += 3) {
      const bool hold = std::string(action) == "feedhold on";
      std::ofstream(dir / "h.plc") << fmt::format("{:.3f} {}\n", ms / 1000.0, action)
                                   << (hold ? fmt::format("{:.3f} feedhold off\n", ms / 1000.0 + 0.1) : "");
      const PathRun r = run_mill_file(dir / "p.nc", dir, " --plc " + (dir / "h.plc").string());
      ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
      const Trace& tr = r.trace;
      ASSERT_GT(tr.p.size(), 300u) << action << " " << ms;
      for (std::size_t i = 2; i < tr.p.size(); ++i)
        for (int k = 0; k < 2; ++k) {
          const double a = (tr.p[i][k] - 2 * tr.p[i - 1][k] + tr.p[i - 2][k]) / (kDt * kDt);
          ASSERT_LE(std::fabs(a), 3000 + 5.0) << action << " at " << ms << " ms, axis " << k << " t " << tr.t[i];
        }
    }
}

TEST(CornerBlending, SyntaxErrorsNameIdFileAndLine) {
  auto expect_error = [](const std::string& name, const std::string& text, const std::string& id, const std::string& line) {
    const PathRun r = run_mill(name, text);
    EXPECT_EQ(r.cli.exit_code, 1) << r.cli.output;
    EXPECT_NE(r.cli.output.find(id), std::string::npos) << r.cli.output;
    EXPECT_NE(r.cli.output.find("p.nc:" + line), std::string::npos) << r.cli.output;
  };
  expect_error("cb-mode", "N10 G1 X10 F1200\nN20 #CONTOUR MODE [DIST PATH_DEV=1]\nN30 M30\n", "930350", "2");
  expect_error("cb-param", "N10 G1 X10 F1200\nN20 #CONTOUR MODE [DEV TRACK_DEV=1]\nN30 M30\n", "930350", "2");
  expect_error("cb-range", "N10 G1 X10 F1200\n\nN20 #CONTOUR MODE [DEV PATH_DEV=0]\nN30 M30\n", "930351", "3");
  expect_error("cb-g61", "N10 G1 X10 F1200\nN20 G61\nN30 M30\n", "930352", "2");
  expect_error("cb-g61-g60", "N10 G1 X10 F1200\nN20 G61 G60 X20\nN30 M30\n", "930352", "2");
  expect_error("cb-groups", "N10 G261 G260 G1 X10 F1200\nN30 M30\n", "920", "1");
}

// G61 blends the corner at the end of its own block only (N40's G261 is
// not asserted here: see the example test); a G60 block, a
// block with an M function and a dwell keep their exact stop.
TEST(CornerBlending, G61BlendsOneCornerAndStopsStayStops) {
  const PathRun r = run_mill("cb-g61", "N5 #CONTOUR MODE [DEV PATH_DEV=0.02]\nN10 G1 G61 X10 F1200\nN20 Y10\n"
                                       "N30 X0\nN40 G261 Y0\nN50 G60 X-10\nN60 Y-10\nN70 M8 X-20\nN80 Y-20\nN90 M30\n");
  ASSERT_EQ(r.cli.exit_code, 0) << r.cli.output;
  EXPECT_NEAR(distance_to_trace(r.trace, {10, 0, 0}), 0.02, 0.002);    // G61: blended
  EXPECT_LT(distance_to_trace(r.trace, {10, 10, 0}), 0.001);           // N20: sharp
  EXPECT_LT(distance_to_trace(r.trace, {0, 10, 0}), 0.001);            // N30: sharp
  EXPECT_LT(distance_to_trace(r.trace, {-10, 0, 0}), 1e-6);            // N50 G60: exact stop
  EXPECT_LT(distance_to_trace(r.trace, {-10, -10, 0}), 1e-6);          // N70 has M8: stops before it
  EXPECT_LT(distance_to_trace(r.trace, {-20, -10, 0}), 1e-6);          // ... and after it
}

}  // namespace
}  // namespace nck::app
