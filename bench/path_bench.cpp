// Cycle time of the common benchmark program (issue 12): the 200,000-block
// milling program of bench/common_program.py (chords and small
// semicircles on a 50 mm circle at F1200/F1500), generated here by the same
// rule so the benchmark needs nothing outside the repository. Reported:
// simulated time / (path length / feed), and simulated seconds per wall
// second. Arg: blocks (2000 for a quick look, 200000 for the figure).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <memory>

#include "nck/config/load.hpp"
#include "nck/sim/dry_run.hpp"

namespace {

struct Workload {
  std::filesystem::path file;
  double ideal_s = 0;    // every move at its programmed feed (G0 at 500 mm/s), no ramps
  double length_mm = 0;  // programmed path length
};

double round3(double v) { return std::round(v * 1000.0) / 1000.0; }

// The generator of common_program.py, with the ideal time of each move.
Workload write_common_program(int n, const std::string& prelude) {
  Workload w;
  w.file = std::filesystem::temp_directory_path() / fmt::format("nck-common-{}.nc", n);
  std::ofstream out(w.file);
  out << prelude << "G90 G17 G54\nM3 S1000\nG0 X0 Y0 Z5\nG1 Z-1 F300\n";
  w.ideal_s = 5.0 / 500.0 + 6.0 / 5.0;
  w.length_mm = 5.0 + 6.0;
  double cx = 0, cy = 0;
  for (int i = 0; i < n; ++i) {
    const double x = round3(50 * std::cos(i * 0.01)), y = round3(50 * std::sin(i * 0.01));
    const double chord = std::hypot(x - cx, y - cy);
    if (i % 4 == 3) {
      const double mx = (cx + x) / 2, my = (cy + y) / 2;
      out << fmt::format("G2 X{:.3f} Y{:.3f} I{:.4f} J{:.4f} F1200\n", x, y, mx - cx, my - cy);
      w.ideal_s += M_PI * chord / 2 / 20.0;
      w.length_mm += M_PI * chord / 2;
    } else {
      out << fmt::format("G1 X{:.3f} Y{:.3f} F1500\n", x, y);
      w.ideal_s += chord / (i == 0 ? 500.0 : 25.0);  // the first move starts from X0 Y0 at F1500
      w.length_mm += chord;
    }
    cx = x, cy = y;
  }
  out << "M5\nM2\n";
  return w;
}

// The mill, with every feed and G0 ramp time of its path axes set to tr_s
// when tr_s > 0 (the jerk-limited slopes' rows).
nck::config::Machine mill(double tr_s) {
  auto loaded = nck::config::load_machine(std::string(NCK_SOURCE_DIR) + "/examples/mill");
  nck::config::Machine m = *loaded.machine;
  if (tr_s > 0)
    for (auto& ax : m.axes)
      for (auto& g : ax.gears) g.tr_acc_up_s = g.tr_acc_down_s = g.tr_dec_up_s = g.tr_dec_down_s = g.tr_rapid_s = tr_s;
  return m;
}

void run_common(benchmark::State& state, const std::string& prelude, double tr_s = 0) {
  const nck::config::Machine m = mill(tr_s);
  const Workload w = write_common_program(static_cast<int>(state.range(0)), prelude);
  auto out = std::make_unique<nck::kernel::TickOutput>();
  double simulated_s = 0, last_s = 0, travelled_mm = 0, ramp_pct = 0;
  // X, Y, Z: the mill's axis lists in channel order.
  std::array<nck::config::GearStage, 3> limits{};
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& ax = m.axes[static_cast<std::size_t>(m.channels[0].axes[k].axis_index)];
    limits[k] = ax.gear(ax.initial_gear_stage);
  }
  const double dt_s = m.cycle_time_us * 1e-6;
  struct {
    double v_share = 0, a_share = 0;  // largest |v| / max_speed_mm_s and |a| / a_max of any axis
  } worst;
  nck::prep::BlendStats blends{};
  for (auto _ : state) {
    auto run = nck::sim::DryRun::create(m, {w.file});
    if (!run) {
      state.SkipWithError("cannot create the run");
      return;
    }
    // The path the set points travel (X, Y, Z), to state how much of the
    // programmed length blending cuts, and the limit check of the property
    // test on every cycle: no axis beyond max_speed_mm_s or a_max.
    std::array<double, 3> last{}, v_last{};
    std::size_t cycles = 0, ramp_cycles = 0;
    double v_path_last = 0;
    travelled_mm = 0;
    worst = {};
    while (!run->done()) {
      run->step(*out);
      const auto& p = out->channels[0].axis_mcs;
      if (cycles > 0) travelled_mm += std::hypot(p[0] - last[0], p[1] - last[1], p[2] - last[2]);
      for (std::size_t k = 0; k < 3 && cycles > 0; ++k) {
        const double v = (p[k] - last[k]) / dt_s;
        worst.v_share = std::max(worst.v_share, std::fabs(v) / limits[k].max_speed_mm_s);
        if (cycles > 1) worst.a_share = std::max(worst.a_share, std::fabs(v - v_last[k]) / dt_s / limits[k].a_max);
        v_last[k] = v;
      }
      // A ramp: the path speed changes (more than 1 mm/s^2, far below any
      // acceleration of the mill, so rounding never counts).
      const double v_path = out->channels[0].path_velocity_mm_s;
      if (std::fabs(v_path - v_path_last) > 1.0 * dt_s) ++ramp_cycles;
      v_path_last = v_path;
      ++cycles;
      last = {p[0], p[1], p[2]};
    }
    ramp_pct = 100.0 * static_cast<double>(ramp_cycles) / static_cast<double>(std::max<std::size_t>(cycles, 1));
    last_s = run->time_s();
    simulated_s += last_s;
    blends = run->prep(0).blend_stats();
  }
  state.counters["time_ratio"] = last_s / w.ideal_s;
  state.counters["path_short_pct"] = 100.0 * (w.length_mm - travelled_mm) / w.length_mm;
  state.counters["blends"] = static_cast<double>(blends.blends);
  state.counters["parabolas"] = static_cast<double>(blends.parabolas);
  state.counters["blend_short_mm"] = blends.shortfall_mm;
  state.counters["max_dev_mm"] = blends.max_deviation_mm;
  state.counters["sim_s"] = last_s;
  state.counters["ramp_pct"] = ramp_pct;  // share of the cycles in which the path speed changes
  state.counters["max_v_of_vb_max"] = worst.v_share;
  state.counters["max_a_of_a_max"] = worst.a_share;
  // Beyond a limit by more than rounding (1e-6 relative): the run is wrong.
  if (worst.v_share > 1 + 1e-6 || worst.a_share > 1 + 1e-6) state.SkipWithError("an axis exceeded vb_max or a_max");
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated_s, benchmark::Counter::kIsRate);
  std::filesystem::remove(w.file);
}

// The default: velocity look-ahead, no corner blending.
void BM_CommonProgram(benchmark::State& state) { run_common(state, ""); }
BENCHMARK(BM_CommonProgram)->Arg(2000)->Arg(200000)->Unit(benchmark::kMillisecond)->Iterations(1);

// Corner blending on: these lines are prepended (docs/performance.md).
void BM_CommonProgramBlend(benchmark::State& state) {
  run_common(state, "#CONTOUR MODE [DEV PATH_DEV=0.025]\nG261\n");
}
BENCHMARK(BM_CommonProgramBlend)->Arg(2000)->Arg(200000)->Unit(benchmark::kMillisecond)->Iterations(1);

// STEP with corner blending at 0.01 mm (issue 30: the "before" and "after" rows
// of docs/performance.md; the every-cycle limit check stays on).
void BM_CommonProgramBlend001(benchmark::State& state) {
  run_common(state, "#CONTOUR MODE [DEV PATH_DEV=0.01]\nG261\n");
}
BENCHMARK(BM_CommonProgramBlend001)->Arg(20000)->Unit(benchmark::kMillisecond)->Iterations(1);

// The jerk-limited TRAPEZ slope with every ramp time 20 ms (issue 30).
void BM_CommonProgramTrapez(benchmark::State& state) { run_common(state, "#SLOPE [TYPE=TRAPEZ]\n", 0.020); }
BENCHMARK(BM_CommonProgramTrapez)->Arg(2000)->Arg(20000)->Arg(200000)->Unit(benchmark::kMillisecond)->Iterations(1);

// HSC across blocks with the same ramp times (issue 30, third part).
void BM_CommonProgramHsc(benchmark::State& state) { run_common(state, "#SLOPE [TYPE=HSC]\n", 0.020); }
BENCHMARK(BM_CommonProgramHsc)->Arg(2000)->Arg(20000)->Arg(200000)->Unit(benchmark::kMillisecond)->Iterations(1);

// Exact stop at every block (G360): the behaviour before the look-ahead.
void BM_CommonProgramExactStop(benchmark::State& state) { run_common(state, "G360\n"); }
BENCHMARK(BM_CommonProgramExactStop)->Arg(2000)->Arg(200000)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
