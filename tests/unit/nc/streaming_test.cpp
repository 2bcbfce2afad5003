// Streaming: a program of 1,000,000 blocks decodes in bounded memory (the
// decoder keeps no blocks), and the rate is reported.
#include <chrono>
#include <cstdio>

#include "nc_test_util.hpp"

namespace nck::nc::test {
namespace {

long rss_kb() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  long pages = 0, resident = 0;
  if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
  std::fclose(f);
  return resident * 4;
}

TEST(NcStreaming, MillionBlocksInBoundedMemory) {
  auto dir = temp_dir();
  auto p = dir / "big.nc";
  {
    std::FILE* f = std::fopen(p.string().c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs("%BIG\nG1 F1000\n", f);
    for (int i = 0; i < 1'000'000; ++i) std::fprintf(f, "X%d.%03d Y-%d.5 F%d\n", i % 500, i % 1000, i % 70, 1000 + i % 3);
    std::fputs("M30\n", f);
    std::fclose(f);
  }
  long before = rss_kb();
  Decoder dec(p, default_config());
  std::size_t n = 0;
  double last_x = 0;
  auto t0 = std::chrono::steady_clock::now();
  Decoder::Result r;
  while ((r = dec.next()).status == Decoder::Status::block) {
    ++n;
    if (r.block.axes[0]) last_x = *r.block.axes[0];
  }
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  long grown = rss_kb() - before;
  EXPECT_EQ(r.status, Decoder::Status::end);
  EXPECT_EQ(n, 1'000'002u);
  EXPECT_DOUBLE_EQ(last_x, 999'999 % 500 + 0.999);
  EXPECT_LT(grown, 16 * 1024) << "decoder memory grew by " << grown << " kB";
  std::printf("[ info ] %zu blocks in %.3f s = %.2f Mblocks/s (build type of this test binary)\n", n, s,
              static_cast<double>(n) / s / 1e6);
  std::filesystem::remove(p);
}

}  // namespace
}  // namespace nck::nc::test
