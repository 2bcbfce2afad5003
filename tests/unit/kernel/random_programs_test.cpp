// Seeded property test of the whole execution path: mutated example
// programs are decoded, planned and ticked. Whatever the input, the kernel
// ends every run cleanly — program end, an NC error, or still running at
// the cycle limit — with finite set points, and never crashes (ASan/UBSan
// in CI). Count from NCK_PROPERTY_COUNT (default 150).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

#include "nck/config/load.hpp"
#include "nck/sim/dry_run.hpp"
#include "nck/kernel/kernel.hpp"
#include "nck/nc/decoder.hpp"

namespace nck::kernel {
namespace {

std::string read(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// Replaces, inserts or deletes a few characters, biased towards NC-ish ones.
std::string mutate(std::string text, std::mt19937& rng) {
  static const std::string alphabet = "0123456789.-+XYZIJKRFGMS[]()=#;\n ";
  std::uniform_int_distribution<int> edits(1, 6);
  for (int n = edits(rng); n > 0 && !text.empty(); --n) {
    std::uniform_int_distribution<std::size_t> at(0, text.size() - 1);
    std::uniform_int_distribution<std::size_t> ch(0, alphabet.size() - 1);
    const std::size_t p = at(rng);
    switch (rng() % 3) {
      case 0: text[p] = alphabet[ch(rng)]; break;
      case 1: text.insert(p, 1, alphabet[ch(rng)]); break;
      default: text.erase(p, 1); break;
    }
  }
  return text;
}

TEST(RandomPrograms, KernelEndsCleanlyWithFiniteSetPoints) {
  const std::string root = NCK_SOURCE_DIR;
  const char* env = std::getenv("NCK_PROPERTY_COUNT");
  const int count = env ? std::atoi(env) : 150;
  config::LoadResult mill = config::load_machine(root + "/examples/mill");
  ASSERT_TRUE(mill.ok());
  const std::string sources[] = {read(root + "/examples/mill/contour.nc"), read(root + "/examples/mill/offsets.nc"),
                                 read(root + "/examples/mill/spindle.nc"), read(root + "/examples/mill/coordinates.nc")};
  const auto dir = std::filesystem::temp_directory_path() / ("nck_random_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  for (int i = 0; i < count; ++i) {
    std::mt19937 rng(static_cast<std::uint32_t>(7000 + i));
    const auto program = dir / "p.nc";
    std::ofstream(program) << mutate(sources[static_cast<std::size_t>(i) % std::size(sources)], rng);
    auto run = sim::DryRun::create(*mill.machine, {program});
    ASSERT_TRUE(run.has_value());
    auto out = std::make_unique<TickOutput>();
    for (int cycle = 0; cycle < 60'000 && !run->done(); ++cycle) {
      run->step(*out);
      for (std::size_t j = 0; j < 3; ++j)
        ASSERT_TRUE(std::isfinite(out->channels[0].axis_mcs[j])) << "seed " << 7000 + i;
      for (std::size_t s = 0; s < run->kernel().spindle_count(); ++s)
        ASSERT_TRUE(std::isfinite(out->spindles[s].set_rpm)) << "seed " << 7000 + i;
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace nck::kernel
