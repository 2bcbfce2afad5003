// Decoder throughput (blocks/s) on a generated G1/G2 program, and the peak
// memory of decoding a 1,000,000-block program (bounded by streaming).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <sys/resource.h>

#include "nck/nc/decoder.hpp"

namespace {

std::filesystem::path generated_program(std::size_t blocks) {
  auto path = std::filesystem::temp_directory_path() / fmt::format("nck_bench_{}.nc", blocks);
  if (std::filesystem::exists(path)) return path;
  std::FILE* f = std::fopen(path.c_str(), "w");
  fmt::print(f, "%bench\nN1 G17 G90 F1000\n");
  for (std::size_t i = 0; i < blocks; ++i) {
    const double x = static_cast<double>(i % 1000) * 0.1;
    if (i % 2 == 0)
      fmt::print(f, "N{} G1 X{:.3f} Y{:.3f} Z-1.5\n", i + 2, x, x * 0.5);
    else
      fmt::print(f, "N{} G2 X{:.3f} Y{:.3f} I5 J0\n", i + 2, x, x * 0.5);
  }
  fmt::print(f, "M30\n");
  std::fclose(f);
  return path;
}

nck::nc::DecoderConfig config() {
  nck::nc::DecoderConfig c;
  c.axis_names = {"X", "Y", "Z"};
  c.spindle_names = {"S1"};
  c.main_spindle = "S1";
  return c;
}

std::size_t decode_all(const std::filesystem::path& p) {
  nck::nc::Decoder d(p, config());
  std::size_t n = 0;
  for (;;) {
    auto r = d.next();
    if (r.status != nck::nc::Decoder::Status::block) break;
    benchmark::DoNotOptimize(r.block);
    ++n;
    if (r.block.program_end) break;
  }
  return n;
}

void BM_Decode200k(benchmark::State& state) {
  const auto p = generated_program(200'000);
  std::size_t blocks = 0;
  for (auto _ : state) blocks += decode_all(p);
  state.SetItemsProcessed(static_cast<std::int64_t>(blocks));
  state.counters["blocks_per_s"] =
      benchmark::Counter(static_cast<double>(blocks), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Decode200k)->Unit(benchmark::kMillisecond);

// Peak resident memory of the whole process after decoding 1M blocks.
void BM_Decode1MPeakMemory(benchmark::State& state) {
  const auto p = generated_program(1'000'000);
  for (auto _ : state) benchmark::DoNotOptimize(decode_all(p));
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  state.counters["peak_rss_MiB"] = static_cast<double>(u.ru_maxrss) / 1024.0;
}
BENCHMARK(BM_Decode1MPeakMemory)->Unit(benchmark::kMillisecond)->Iterations(1);

// A main program calling one global subroutine file 5,000 times, decoded
// with and without the file cache (FCT_USE_CACHED_FILES); range(0) = cache on.
void BM_DecodeRepeatedCalls(benchmark::State& state) {
  const auto dir = std::filesystem::temp_directory_path() / "nck_bench_calls";
  std::filesystem::create_directories(dir);
  {
    std::FILE* sub = std::fopen((dir / "sub.nc").c_str(), "w");
    fmt::print(sub, "%sub\n");
    for (int i = 0; i < 20; ++i) fmt::print(sub, "N{} G1 X{} Y{}\n", i, i, i * 0.5);
    fmt::print(sub, "M17\n");
    std::fclose(sub);
    std::FILE* main = std::fopen((dir / "main.nc").c_str(), "w");
    fmt::print(main, "%main\nG1 F1000\n$FOR P1 = 1, 5000, 1\nL sub.nc\n$ENDFOR\nM30\n");
    std::fclose(main);
  }
  nck::nc::DecoderConfig c = config();
  c.use_cached_files = state.range(0) != 0;
  c.max_cache_number = 4;
  c.max_cache_size_kb = 1024;
  std::size_t blocks = 0;
  for (auto _ : state) {
    nck::nc::Decoder d(dir / "main.nc", c);
    for (;;) {
      auto r = d.next();
      if (r.status != nck::nc::Decoder::Status::block || r.block.program_end) break;
      ++blocks;
    }
  }
  state.counters["blocks_per_s"] = benchmark::Counter(static_cast<double>(blocks), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DecodeRepeatedCalls)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
