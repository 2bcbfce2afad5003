#include "nck/plc/ext_command.hpp"

#include <gtest/gtest.h>

namespace nck::plc {
namespace {

ExtSpindleCommand cmd(ExtFunction fn, double rev) {
  ExtSpindleCommand c;
  c.fn = fn;
  c.has_rev = true;
  c.rev_rpm = rev;
  c.spindle = 1;
  return c;
}

TEST(ExtCommandQueue, RunsInOrderOfArrival) {
  ExtCommandQueue q;
  EXPECT_EQ(q.push(cmd(ExtFunction::m3, 500)), 1u);
  EXPECT_EQ(q.push(cmd(ExtFunction::m4, 600)), 2u);
  EXPECT_EQ(q.push(cmd(ExtFunction::m5, 0)), 3u);
  ExtSpindleCommand out;
  ASSERT_TRUE(q.pop(out));
  EXPECT_EQ(out.seq, 1u);
  EXPECT_EQ(out.fn, ExtFunction::m3);
  EXPECT_DOUBLE_EQ(out.rev_rpm, 500);
  ASSERT_TRUE(q.pop(out));
  EXPECT_EQ(out.fn, ExtFunction::m4);
  ASSERT_TRUE(q.pop(out));
  EXPECT_EQ(out.fn, ExtFunction::m5);
  EXPECT_FALSE(q.pop(out));
  EXPECT_TRUE(q.empty());
}

TEST(ExtCommandQueue, FullQueueRejects) {
  ExtCommandQueue q;
  for (std::size_t i = 0; i < ExtCommandQueue::kCapacity; ++i)
    EXPECT_NE(q.push(cmd(ExtFunction::m3, static_cast<double>(i))), 0u);
  EXPECT_EQ(q.push(cmd(ExtFunction::m3, 1)), 0u);
  EXPECT_EQ(q.size(), ExtCommandQueue::kCapacity);
  ExtSpindleCommand out;
  ASSERT_TRUE(q.pop(out));
  EXPECT_DOUBLE_EQ(out.rev_rpm, 0);  // the oldest
  EXPECT_NE(q.push(cmd(ExtFunction::m3, 1)), 0u);
  q.clear();
  EXPECT_TRUE(q.empty());
}

TEST(ExtCommandQueue, EachCommandIsAcknowledged) {
  ExtCommandQueue q;
  auto a = q.push(cmd(ExtFunction::m3, 500));
  auto b = q.push(cmd(ExtFunction::m19, 100));
  EXPECT_FALSE(q.acknowledged(a));
  q.acknowledge(a);
  EXPECT_TRUE(q.acknowledged(a));
  EXPECT_FALSE(q.acknowledged(b));
  EXPECT_EQ(q.last_acknowledged(), a);
  q.acknowledge(b);
  EXPECT_EQ(q.last_acknowledged(), b);
  q.acknowledge(0);  // ignored
  EXPECT_EQ(q.last_acknowledged(), b);
  // The history is bounded: old acknowledgements are forgotten, never a crash.
  for (std::uint32_t s = 100; s < 100 + ExtCommandQueue::kAckHistory; ++s) q.acknowledge(s);
  EXPECT_FALSE(q.acknowledged(a));
  EXPECT_TRUE(q.acknowledged(100 + ExtCommandQueue::kAckHistory - 1));
}

}  // namespace
}  // namespace nck::plc
