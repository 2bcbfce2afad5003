#pragma once
// Shared helpers for the offset-chain tests.
#include <gtest/gtest.h>

#include "nck/frames/offset_chain.hpp"

namespace nck::frames::test {

inline constexpr std::size_t kAxes = 4;  // X Y Z C

inline OffsetChain make_chain(bool tool_direct = false) {
  ChainConfig c;
  c.axis_count = kAxes;
  c.move_tool_offsets_directly = tool_direct;
  return OffsetChain(c);
}

inline PcsPoint pcs(double x, double y, double z, double c = 0) {
  PcsPoint p;
  p.pos_mm[0] = x;
  p.pos_mm[1] = y;
  p.pos_mm[2] = z;
  p.pos_mm[3] = c;
  return p;
}

inline McsPoint mcs(double x, double y, double z, double c = 0) {
  McsPoint p;
  p.pos_mm[0] = x;
  p.pos_mm[1] = y;
  p.pos_mm[2] = z;
  p.pos_mm[3] = c;
  return p;
}

inline void expect_point(const AxisValues& got, const AxisValues& want, double tol = 1e-9) {
  for (std::size_t j = 0; j < kAxes; ++j) EXPECT_NEAR(got[j], want[j], tol) << "axis " << j;
}

// Zero-offset table with G54 = X10 Y-5 (P-ZERO-00003 versch 100000 = 10 mm).
inline ZeroOffsetTable zero_table() {
  ZeroOffsetTable t;
  t.groups[1].offset_mm[0] = 10.0;
  t.groups[1].offset_mm[1] = -5.0;
  t.groups[2].offset_mm[2] = 3.0;   // G55 Z3
  t.groups[7].offset_mm[0] = 70.0;  // G159=7
  t.groups[0].offset_mm[0] = 7.0;   // G53 group, used only with g53_available
  return t;
}

inline void ok(const OffsetChain::Result& r) {
  ASSERT_TRUE(r.has_value()) << "error " << number(r.error().id);
}

inline void fails_with(const OffsetChain::Result& r, ErrorId id) {
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(number(r.error().id), number(id));
}

}  // namespace nck::frames::test
