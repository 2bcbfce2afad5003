// Nanoseconds per cycle on the mill example (3 path axes moving on a long
// contour): the simulated machine's read and write plus Kernel::tick(), with
// preparation topping the command queue up as `nck run` does; and simulated
// seconds per wall second of a whole run.
#include <benchmark/benchmark.h>

#include <memory>

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

// state.range(0): 0 = contour.nc (path only), 1 = spindle.nc (path + S1/S2 running)
void BM_Tick(benchmark::State& state) {
  const char* program = state.range(0) == 0 ? "contour.nc" : "spindle.nc";
  const nck::config::Machine m = mill();
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
BENCHMARK(BM_Tick)->Arg(0)->Arg(1);

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

}  // namespace

BENCHMARK_MAIN();
