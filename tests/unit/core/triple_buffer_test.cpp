// The live kernel's state hand-over: the reader gets the newest value, never
// a torn one, and neither side waits.
#include <atomic>
#include <cstdint>
#include <thread>

#include <gtest/gtest.h>

#include "nck/core/triple_buffer.hpp"

namespace nck {
namespace {

struct Pair {
  std::uint64_t a = 0, b = 0;  // always equal when written
};

TEST(TripleBuffer, ReaderSeesTheNewestValueOnce) {
  TripleBuffer<int> tb;
  EXPECT_FALSE(tb.take());
  tb.back() = 1;
  tb.publish();
  tb.back() = 2;
  tb.publish();
  ASSERT_TRUE(tb.take());
  EXPECT_EQ(tb.front(), 2);  // 1 was skipped: only the newest counts
  EXPECT_FALSE(tb.take());
  EXPECT_EQ(tb.front(), 2);
  tb.back() = 3;
  tb.publish();
  ASSERT_TRUE(tb.take());
  EXPECT_EQ(tb.front(), 3);
}

TEST(TripleBuffer, NoTornValueAcrossThreads) {
  TripleBuffer<Pair> tb;
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (std::uint64_t i = 1; i <= 200000; ++i) {
      tb.back() = Pair{i, i};
      tb.publish();
    }
    done = true;
  });
  std::uint64_t last = 0, torn = 0, backwards = 0;
  for (;;) {
    const bool finished = done.load();
    if (!tb.take()) {
      if (finished) break;
      continue;
    }
    const Pair p = tb.front();
    torn += p.a != p.b;
    backwards += p.a < last;
    last = p.a;
  }
  writer.join();
  EXPECT_EQ(torn, 0u);
  EXPECT_EQ(backwards, 0u);
  EXPECT_EQ(tb.front().a, 200000u);
}

}  // namespace
}  // namespace nck
