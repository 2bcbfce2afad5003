// Seed FCT-S1 2.3.2 (M19 direction rules, preferred direction 60254) and
// 2.6 (speed reached band from vb_prozent, zero speed below vb_min_null).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "nck/spindle/positioning.hpp"

namespace nck::spindle {
namespace {

TEST(Positioning, WrapModulo) {
  EXPECT_DOUBLE_EQ(wrap_modulo(370, 0, 360), 10);
  EXPECT_DOUBLE_EQ(wrap_modulo(-10, 0, 360), 350);
  EXPECT_DOUBLE_EQ(wrap_modulo(360, 0, 360), 0);
  EXPECT_DOUBLE_EQ(wrap_modulo(190, -180, 180), -170);
  EXPECT_DOUBLE_EQ(wrap_modulo(std::nan(""), 0, 360), 0);
  EXPECT_DOUBLE_EQ(wrap_modulo(5, 10, 10), 10);
}

TEST(Positioning, M19ProgrammedDirection) {
  EXPECT_DOUBLE_EQ(m19_travel_deg(10, 100, Direction::positive, 0, 0, 360), 90);
  EXPECT_DOUBLE_EQ(m19_travel_deg(10, 100, Direction::negative, 0, 0, 360), -270);
  EXPECT_DOUBLE_EQ(m19_travel_deg(100, 10, Direction::positive, 0, 0, 360), 270);
  EXPECT_DOUBLE_EQ(m19_travel_deg(10, 460, Direction::positive, 0, 0, 360), 90);  // target wrapped
  // Programmed direction wins over the current rotation.
  EXPECT_DOUBLE_EQ(m19_travel_deg(10, 100, Direction::negative, 600, 0, 360), -270);
}

TEST(Positioning, M19WithoutDirection) {
  // From standstill: shortest path.
  EXPECT_DOUBLE_EQ(m19_travel_deg(10, 100, Direction::none, 0, 0, 360), 90);
  EXPECT_DOUBLE_EQ(m19_travel_deg(10, 300, Direction::none, 0, 0, 360), -70);
  EXPECT_DOUBLE_EQ(m19_travel_deg(0, 180, Direction::none, 0, 0, 360), 180);  // tie: positive
  // From rotation: keep the current direction.
  EXPECT_DOUBLE_EQ(m19_travel_deg(10, 300, Direction::none, 500, 0, 360), 290);
  EXPECT_DOUBLE_EQ(m19_travel_deg(10, 100, Direction::none, -500, 0, 360), -270);
  EXPECT_DOUBLE_EQ(m19_travel_deg(50, 50, Direction::none, 0, 0, 360), 0);
}

TEST(Positioning, PreferredDirection60254) {
  config::AxisConfig ax;
  EXPECT_TRUE(check_preferred_direction(ax, Direction::negative).has_value());  // not configured
  ax.has_preferred_direction = true;
  ax.preferred_direction_positive = true;
  EXPECT_TRUE(check_preferred_direction(ax, Direction::positive).has_value());
  auto bad = check_preferred_direction(ax, Direction::negative);
  ASSERT_FALSE(bad.has_value());
  EXPECT_EQ(number(bad.error()), 60254u);
  EXPECT_TRUE(check_preferred_direction(ax, Direction::none).has_value());
  ax.preferred_direction_positive = false;
  EXPECT_FALSE(check_preferred_direction(ax, Direction::positive).has_value());
  EXPECT_EQ(preferred_direction(ax), Direction::negative);
}

TEST(Positioning, SpeedReachedBandEdges) {
  // Default vb_prozent 100 (0.1 %) -> +-10 % of 1000 rpm.
  EXPECT_TRUE(speed_reached(900, 1000, 100));
  EXPECT_TRUE(speed_reached(1100, 1000, 100));
  EXPECT_FALSE(speed_reached(899.99, 1000, 100));
  EXPECT_FALSE(speed_reached(1100.01, 1000, 100));
  EXPECT_TRUE(speed_reached(-900, -1000, 100));
  EXPECT_FALSE(speed_reached(1000, -1000, 100));
  // vb_prozent 20 -> +-2 %.
  EXPECT_TRUE(speed_reached(2940, 3000, 20));
  EXPECT_FALSE(speed_reached(2939, 3000, 20));
}

TEST(Positioning, ZeroSpeed) {
  EXPECT_TRUE(zero_speed(0.09, 0.1));   // vb_min_null default 100 mdeg/s
  EXPECT_FALSE(zero_speed(0.1, 0.1));
  EXPECT_FALSE(zero_speed(-0.2, 0.1));
  EXPECT_FALSE(zero_speed(std::nan(""), 0.1));
}

// The inline fast path gives the fmod definition's result bit for bit (the
// traces of every turning spindle depend on it), in and around the range.
TEST(Positioning, WrapModuloIsItsFmodDefinitionBitForBit) {
  const double ranges[][2] = {{0, 360}, {-180, 180}, {10.5, 370.5}, {0, 0.7}, {-1e-3, 359.999}};
  std::uint64_t state = 12345;
  auto next = [&] {  // a small LCG: reproducible, no library randomness
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / static_cast<double>(1ull << 53);
  };
  for (const auto& r : ranges) {
    const double width = r[1] - r[0];
    for (int i = 0; i < 20000; ++i) {
      const double x = r[0] + (next() * 5.0 - 2.0) * width;  // from two turns below to three above
      const double a = detail::wrap_modulo_by_fmod(x, r[0], r[1]), b = wrap_modulo(x, r[0], r[1]);
      ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << x << " in [" << r[0] << ", " << r[1] << ")";
    }
    for (double edge : {r[0], r[1], r[0] - width, r[1] + width, std::nextafter(r[1], r[0]), -0.0}) {
      const double a = detail::wrap_modulo_by_fmod(edge, r[0], r[1]), b = wrap_modulo(edge, r[0], r[1]);
      EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << edge;
    }
  }
  EXPECT_EQ(wrap_modulo(std::nan(""), 0, 360), 0);
}

}  // namespace
}  // namespace nck::spindle
