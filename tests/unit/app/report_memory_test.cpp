// Issue 26, finding 5: the memory of `nck run --report` is bounded by
// design, not by the program: a long program of short blocks and a block
// crawling at F1e-300 stay at a fixed peak RSS. In a plain build (or with
// NCK_PLAIN_BINARY naming a plain nck, as scripts/test.sh does beside the
// ASan suite) the figures: 5,000,000 lines within 64 MiB. Under ASan
// (its shadow memory makes absolute figures meaningless) the growth from a
// 10,000-line run to a 100,000-line run stays within 8 MiB: the issue's
// 500,000 lines took 466 s under ASan+UBSan here, past ctest's 300 s per
// test (docs/robustness.md); before issue 26 the 90,000 lines more cost
// some 18 MiB.
#include <gtest/gtest.h>

#include <cstdlib>
#include <sys/resource.h>

#include "cli_helpers.hpp"

namespace nck::app::testing {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

constexpr double kMiB = 1024.0 * 1024.0;

std::string mill() { return root() + "/examples/mill"; }

struct Measured {
  int exit_code = -1;
  double peak_rss_mib = 0;
};

// Runs `binary` with `args` (no shell: the RSS is nck's own) and reads its peak RSS.
Measured run_measured(const std::string& binary, const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(binary.c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    if (kSanitized) {  // freed memory waits in ASan's quarantine (256 MB): the RSS would show it, not what nck keeps
      const char* old = std::getenv("ASAN_OPTIONS");
      const std::string options = std::string(old != nullptr ? old : "") +
                                  ":quarantine_size_mb=1:thread_local_quarantine_size_kb=64";
      setenv("ASAN_OPTIONS", options.c_str(), 1);
    }
    execv(binary.c_str(), argv.data());
    _exit(127);
  }
  Measured m;
  int status = 0;
  struct rusage ru{};
  if (pid < 0 || wait4(pid, &status, 0, &ru) != pid) return m;
  m.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  m.peak_rss_mib = static_cast<double>(ru.ru_maxrss) * 1024.0 / kMiB;
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

// The nck whose absolute figures are checked, if any.
std::string plain_binary() {
  if (const char* p = std::getenv("NCK_PLAIN_BINARY"); p != nullptr && *p != '\0') return p;
  return kSanitized ? std::string() : std::string(NCK_BINARY);
}

TEST(ReportMemory, LongProgramOfShortBlocks) {
  const auto dir = temp_dir("report_memory_long");
  if (kSanitized) {
    const Measured small = run_with_report(NCK_BINARY, short_blocks(dir, 10'000), dir);
    const Measured big = run_with_report(NCK_BINARY, short_blocks(dir, 100'000), dir);
    ASSERT_EQ(small.exit_code, 0);
    ASSERT_EQ(big.exit_code, 0);
    EXPECT_LE(big.peak_rss_mib - small.peak_rss_mib, 8.0)
        << "10,000 lines: " << small.peak_rss_mib << " MiB, 100,000 lines: " << big.peak_rss_mib << " MiB";
  }
  if (const std::string plain = plain_binary(); !plain.empty()) {
    const Measured m = run_with_report(plain, short_blocks(dir, 5'000'000), dir);
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
  }
  if (const std::string plain = plain_binary(); !plain.empty()) {
    const Measured m = run_with_report(plain, p, dir, {"--max-time", "5000"});
    ASSERT_EQ(m.exit_code, 1);
    EXPECT_LE(m.peak_rss_mib, 64.0) << "5,000,000 cycles of a crawling block";
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace nck::app::testing
