#include "nck/core/fixed_vector.hpp"
#include "nck/core/ring_buffer.hpp"

#include <gtest/gtest.h>

namespace nck {

TEST(FixedVector, RefusesPastCapacity) {
  FixedVector<int, 2> v;
  EXPECT_TRUE(v.push_back(1));
  EXPECT_TRUE(v.push_back(2));
  EXPECT_FALSE(v.push_back(3));
  EXPECT_EQ(v.size(), 2u);
  EXPECT_EQ(v[1], 2);
}

TEST(RingBuffer, IsFifoAcrossWrapAround) {
  RingBuffer<int, 3> r;
  for (int round = 0; round < 5; ++round) {
    EXPECT_TRUE(r.push(round));
    EXPECT_TRUE(r.push(round + 100));
    EXPECT_EQ(r.front(), round);
    EXPECT_EQ(r.at(1), round + 100);
    r.pop();
    r.pop();
    EXPECT_TRUE(r.empty());
  }
  r.push(1); r.push(2); r.push(3);
  EXPECT_FALSE(r.push(4));
}

}  // namespace nck
