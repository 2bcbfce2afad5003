// Issue 26, finding 5: the memory of `nck run --report` is bounded by
// design, not by the program: a long program of short blocks and a block
// crawling at F1e-300 stay at a fixed peak RSS. In a plain build (README
// command (2) runs these in one beside the ASan suite, scripts/test.sh) the
// issue's figures: 5,000,000 lines within 64 MiB. Under ASan (its shadow
// memory makes absolute figures meaningless) the growth from a 50,000-line
// run to a 500,000-line run stays within 8 MiB.
#include <gtest/gtest.h>

#include <cstdlib>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

struct Measured {
  int exit_code = -1;
  double peak_rss_mib = 0;
};

// Runs `binary` with `args` through the peak_rss launcher (tests/tools): the
// figure is nck's own, not the test process's memory that a child forked
// from it would start with (under ASan some 100 MiB).
Measured run_measured(const std::string& binary, const std::vector<std::string>& args) {
  const auto out = std::filesystem::temp_directory_path() / ("nck_peak_rss_" + std::to_string(getpid()));
  std::string cmd = std::string(NCK_PEAK_RSS) + " " + out.string() + " " + binary;
  for (const std::string& a : args) cmd += " '" + a + "'";
  if (kSanitized)  // freed memory waits in ASan's quarantine (256 MB): the RSS would show it, not what nck keeps
    cmd = "ASAN_OPTIONS=\"$ASAN_OPTIONS:quarantine_size_mb=1:thread_local_quarantine_size_kb=64\" " + cmd;
  Measured m;
  if (std::system(cmd.c_str()) != 0) return m;
  std::ifstream(out) >> m.exit_code >> m.peak_rss_mib;  // KiB for now
  m.peak_rss_mib /= 1024.0;
  std::filesystem::remove(out);
  return m;
}

// `lines` short blocks, each a line of its own (the per-line table's worst
// case): feed changes, several per cycle, and every tenth a 1 µm move (a
// backplot vertex each).
std::filesystem::path short_blocks(const std::filesystem::path& dir, std::size_t lines) {
  const auto p = dir / ("short_" + std::to_string(lines) + ".nc");
  std::ofstream out(p, std::ios::binary);
  out << "G90 G1 F60000\n";
  for (std::size_t i = 0; i < lines; ++i) {
    if (i % 10 == 0) out << "X" << (i % 20 == 0 ? "0.001" : "0") << "\n";
    else out << "F" << 1000 + i % 7 << "\n";
  }
  out << "M30\n";
  return p;
}

Measured run_with_report(const std::string& binary, const std::filesystem::path& program,
                         const std::filesystem::path& dir, std::vector<std::string> extra = {}) {
  std::vector<std::string> args{"run", mill(), program.string(), "--no-progress", "--report", (dir / "r.html").string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_measured(binary, args);
}

TEST(ReportMemory, LongProgramOfShortBlocks) {
  const auto dir = temp_dir("report_memory_long");
  if (kSanitized) {
    const Measured small = run_with_report(NCK_BINARY, short_blocks(dir, 50'000), dir);
    const Measured big = run_with_report(NCK_BINARY, short_blocks(dir, 500'000), dir);
    ASSERT_EQ(small.exit_code, 0);
    ASSERT_EQ(big.exit_code, 0);
    EXPECT_LE(big.peak_rss_mib - small.peak_rss_mib, 8.0)
        << "50,000 lines: " << small.peak_rss_mib << " MiB, 500,000 lines: " << big.peak_rss_mib << " MiB";
  } else {
    const Measured m = run_with_report(NCK_BINARY, short_blocks(dir, 5'000'000), dir);
    ASSERT_EQ(m.exit_code, 0);
    EXPECT_LE(m.peak_rss_mib, 64.0) << "5,000,000 lines";
  }
  std::filesystem::remove_all(dir);
}

// One block at F1e-300: every cycle's step underflows; it used to become a
// vertex of the backplot each cycle.
TEST(ReportMemory, CrawlingBlock) {
  const auto dir = temp_dir("report_memory_crawl");
  const auto p = dir / "crawl.nc";
  std::ofstream(p) << "G1 X10 F1e-300\nM30\n";
  if (kSanitized) {
    const Measured small = run_with_report(NCK_BINARY, p, dir, {"--max-time", "50"});
    const Measured big = run_with_report(NCK_BINARY, p, dir, {"--max-time", "500"});
    ASSERT_EQ(small.exit_code, 1);  // the simulated-time limit
    ASSERT_EQ(big.exit_code, 1);
    EXPECT_LE(big.peak_rss_mib - small.peak_rss_mib, 8.0)
        << "50 s: " << small.peak_rss_mib << " MiB, 500 s: " << big.peak_rss_mib << " MiB";
  } else {
    const Measured m = run_with_report(NCK_BINARY, p, dir, {"--max-time", "5000"});
    ASSERT_EQ(m.exit_code, 1);
    EXPECT_LE(m.peak_rss_mib, 64.0) << "5,000,000 cycles of a crawling block";
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace nck::app::testing
