// Nanoseconds per Kernel::tick() on the mill example (3 path axes moving on
// a long contour), and simulated seconds per wall second of a whole run.
#include <benchmark/benchmark.h>

#include "nck/config/load.hpp"
#include "nck/kernel/decoder_setup.hpp"
#include "nck/kernel/kernel.hpp"
#include "nck/nc/decoder.hpp"

namespace {

struct Setup {
  nck::config::Machine machine;
  nck::kernel::Kernel kernel;
  std::unique_ptr<nck::nc::Decoder> decoder;
  bool fed = false;

  explicit Setup(const char* program = "contour.nc") {
    auto r = nck::config::load_machine(std::string(NCK_SOURCE_DIR) + "/examples/mill");
    machine = *r.machine;
    (void)kernel.configure(machine);
    decoder = std::make_unique<nck::nc::Decoder>(
        std::string(NCK_SOURCE_DIR) + "/examples/mill/" + program,
        nck::kernel::decoder_config(machine, 0));
  }
  void feed() {
    while (!fed && kernel.queue_space(0) > 0) {
      auto r = decoder->next();
      if (r.status != nck::nc::Decoder::Status::block) { fed = true; break; }
      kernel.push_block(0, r.block, decoder->file_name(r.block.file_id));
      fed = r.block.program_end;
    }
  }
};

// state.range(0): 0 = contour.nc (path only), 1 = spindle.nc (path + S1/S2 running)
void BM_Tick(benchmark::State& state) {
  const char* program = state.range(0) == 0 ? "contour.nc" : "spindle.nc";
  auto s = std::make_unique<Setup>(program);
  nck::kernel::TickInput in;
  nck::kernel::TickOutput out;
  for (auto _ : state) {
    if (s->kernel.all_channels_done()) {
      state.PauseTiming();
      s = std::make_unique<Setup>(program);
      state.ResumeTiming();
    }
    s->feed();  // a no-op once the whole program is queued
    s->kernel.tick(in, out);
    benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_Tick)->Arg(0)->Arg(1);

void BM_WholeRun(benchmark::State& state) {
  double simulated_s = 0;
  for (auto _ : state) {
    Setup s;
    nck::kernel::TickInput in;
    nck::kernel::TickOutput out;
    while (!s.kernel.all_channels_done()) {
      s.feed();
      s.kernel.tick(in, out);
    }
    simulated_s += static_cast<double>(s.kernel.cycles()) * s.kernel.cycle_time_s();
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated_s, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_WholeRun)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
