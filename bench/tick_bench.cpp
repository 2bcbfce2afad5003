// Nanoseconds per cycle on the mill example (3 path axes moving on a long
// contour): the simulated machine's read and write plus Kernel::tick(), with
// preparation topping the command queue up as `nck run` does; and simulated
// seconds per wall second of a whole run.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <unistd.h>

#include "nck/config/load.hpp"
#include "nck/sim/dry_run.hpp"

namespace {

std::unique_ptr<nck::sim::DryRun> make_run(const nck::config::Machine& m, const char* program) {
  auto run = nck::sim::DryRun::create(m, {std::string(NCK_SOURCE_DIR) + "/examples/mill/" + program});
  return run ? std::make_unique<nck::sim::DryRun>(std::move(*run)) : nullptr;
}

nck::config::Machine mill() {
  return *nck::config::load_machine(std::string(NCK_SOURCE_DIR) + "/examples/mill").machine;
}

// The mill with jerk-limited slopes (issue 30): the path's profile at
// program start (P-CHAN-00071 = 1 TRAPEZ or 3 HSC) and the spindles' ramps
// (getriebe[i].slope_type = 1), set in the loaded machine so that the
// programs stay the same bytes.
nck::config::Machine jerk_mill(nck::SlopeProfile path) {
  nck::config::Machine m = mill();
  for (auto& ch : m.channels) ch.slope_profile = path;
  for (auto& ax : m.axes)
    if (ax.is_spindle())
      for (auto& g : ax.gears) g.slope_type = nck::SlopeProfile::trapez;
  return m;
}

// state.range(0): 0 = contour.nc (path only), 1 = spindle.nc (path + S1/S2
// running), both STEP as the mill's lists say; 2 and 3 the same programs
// under TRAPEZ (path and spindles), 4 and 5 under HSC (the spindles TRAPEZ).
void BM_Tick(benchmark::State& state) {
  const char* program = state.range(0) % 2 == 0 ? "contour.nc" : "spindle.nc";
  const nck::config::Machine m = state.range(0) < 2   ? mill()
                                 : state.range(0) < 4 ? jerk_mill(nck::SlopeProfile::trapez)
                                                      : jerk_mill(nck::SlopeProfile::hsc);
  auto run = make_run(m, program);
  auto out = std::make_unique<nck::kernel::TickOutput>();
  for (auto _ : state) {
    if (run->done()) {
      state.PauseTiming();
      run = make_run(m, program);
      state.ResumeTiming();
    }
    run->step(*out);  // preparation is a no-op once the whole program is queued
    benchmark::DoNotOptimize(*out);
  }
}
BENCHMARK(BM_Tick)->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Arg(4)->Arg(5);

void BM_WholeRun(benchmark::State& state) {
  const nck::config::Machine m = mill();
  double simulated_s = 0;
  auto out = std::make_unique<nck::kernel::TickOutput>();
  for (auto _ : state) {
    auto run = make_run(m, "contour.nc");
    while (!run->done()) run->step(*out);
    simulated_s += run->time_s();
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated_s, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_WholeRun)->Unit(benchmark::kMillisecond);

// BM_TickCycles (docs/performance.md): 3 axes + 3 spindles + distance control. The mill with a third
// spindle S3 (a copy of S2 as logical axis 6), all three turning while X/Y/Z
// move over the sine sheet of its sim.lis; once with #DIST CTRL ON, once
// without. Each cycle (sim read, tick, sim write) is timed on its own:
// median and worst case.
std::filesystem::path three_spindle_mill(bool dist) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("nck_bench_dist_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::copy(std::string(NCK_SOURCE_DIR) + "/examples/mill", dir, fs::copy_options::recursive);
  auto patch = [&](const char* file, const std::string& before, const std::string& lines) {
    std::stringstream s;
    s << std::ifstream(dir / file).rdbuf();
    std::string text = s.str();
    text.insert(text.rfind(before), lines);
    std::ofstream(dir / file) << text;
  };
  std::stringstream s2;
  s2 << std::ifstream(dir / "s2.lis").rdbuf();
  std::string s3 = s2.str();
  s3.replace(s3.find("kopf.achs_nr                      5"), 35, "kopf.achs_nr                      6");
  std::ofstream(dir / "s3.lis") << s3;
  patch("startup.lis", "Ende", "achs_mds[5] s3.lis\nzahl_mds 6\n");
  patch("channel1.lis", "Ende",
        "spdl_anzahl 3\nspindel[2].bezeichnung S3\nspindel[2].log_achs_nr 6\nspindel[2].s_synch MOS\n"
        "spindel[2].m3_synch MOS\nspindel[2].m4_synch MOS\nspindel[2].m5_synch MOS\nspindel[2].m19_synch MOS\n"
        "dist_ctrl[0].i_tn 0\n");
  std::ofstream(dir / "bench.nc") << "G17 G90 G0 X0 Y0 Z2\nS1000 M3\nS2[M3 REV2000]\nS3[M4 REV1500]\n"
                                  << (dist ? "#DIST CTRL ON [SURFACE SET_POS=0]\n" : "")
                                  << "G1 X100 F3000\nG1 Y50\nG1 X0\nG1 Y0\nG1 X100\nG1 Y50\nG1 X0\nG1 Y0\n"
                                  << (dist ? "#DIST CTRL OFF\n" : "") << "M30\n";
  return dir;
}

// state.range(0): 0 / 1 the three-spindle mill without / with distance
// control; 2 the mill example's contour.nc (BM_Tick/0's program), every
// cycle of whole runs.
void BM_TickCycles(benchmark::State& state) {
  const bool dist = state.range(0) == 1, contour = state.range(0) == 2;
  const auto dir = contour ? std::filesystem::path(NCK_SOURCE_DIR) / "examples/mill" : three_spindle_mill(dist);
  const auto loaded = nck::config::load_machine(dir.string());
  if (!loaded.machine) {
    state.SkipWithError("the mill did not load");
    return;
  }
  const nck::config::Machine m = *loaded.machine;
  auto out = std::make_unique<nck::kernel::TickOutput>();
  std::vector<double> ns;
  ns.reserve(1 << 22);
  for (auto _ : state) {
    auto created = nck::sim::DryRun::create(m, {dir / (contour ? "contour.nc" : "bench.nc")});
    if (!created) {
      state.SkipWithError("run not created");
      return;
    }
    nck::sim::DryRun run = std::move(*created);
    while (!run.done() && ns.size() < ns.capacity()) {
      run.prepare();
      const auto t0 = std::chrono::steady_clock::now();
      run.cycle(*out);
      const auto t1 = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(*out);
      ns.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count());
    }
  }
  std::sort(ns.begin(), ns.end());
  state.counters["median_ns"] = ns.empty() ? 0.0 : ns[ns.size() / 2];
  state.counters["p99_ns"] = ns.empty() ? 0.0 : ns[ns.size() * 99 / 100];
  state.counters["worst_ns"] = ns.empty() ? 0.0 : ns.back();
  state.counters["cycles"] = static_cast<double>(ns.size());
  if (!contour) std::filesystem::remove_all(dir);
}
BENCHMARK(BM_TickCycles)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace

BENCHMARK_MAIN();
