#include "nck/plc/hli.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

namespace nck::plc {
namespace {

TEST(HliPosition, FormatFollowsStartupParameter175) {
  EXPECT_EQ(position_format(true), PositionFormat::scaled_32bit);
  EXPECT_EQ(position_format(false), PositionFormat::high_res_64bit);
}

TEST(HliPosition, Scaled32BitIsTenThousandthDegree) {
  // 123.4567 deg in the list unit 0.0001 deg
  auto p = encode_position(123.4567, PositionFormat::scaled_32bit);
  EXPECT_EQ(p.raw, 1234567);
  EXPECT_FALSE(p.saturated);
  EXPECT_DOUBLE_EQ(decode_position(1234567, PositionFormat::scaled_32bit), 123.4567);
  EXPECT_EQ(encode_position(-90.0, PositionFormat::scaled_32bit).raw, -900000);
  // A finer fraction is rounded to the nearest unit.
  EXPECT_EQ(encode_position(0.00016, PositionFormat::scaled_32bit).raw, 2);
}

TEST(HliPosition, HighRes64BitKeepsWhat32BitLoses) {
  auto p = encode_position(123.4567891, PositionFormat::high_res_64bit);
  EXPECT_EQ(p.raw, 1234567891);
  EXPECT_FALSE(p.saturated);
  EXPECT_NEAR(decode_position(p.raw, PositionFormat::high_res_64bit), 123.4567891, 1e-12);
  // The same value in 32-bit loses the last three digits.
  EXPECT_EQ(encode_position(123.4567891, PositionFormat::scaled_32bit).raw, 1234568);
}

TEST(HliPosition, Scaled32BitSaturatesBeyondInt32) {
  // 300000 mm = 3e9 units of 0.1 um does not fit into 32 bits ...
  auto p = encode_position(300000.0, PositionFormat::scaled_32bit);
  EXPECT_TRUE(p.saturated);
  EXPECT_EQ(p.raw, std::numeric_limits<std::int32_t>::max());
  auto n = encode_position(-300000.0, PositionFormat::scaled_32bit);
  EXPECT_TRUE(n.saturated);
  EXPECT_EQ(n.raw, std::numeric_limits<std::int32_t>::min());
  // ... but does in 64 bits.
  auto h = encode_position(300000.0, PositionFormat::high_res_64bit);
  EXPECT_FALSE(h.saturated);
  EXPECT_EQ(h.raw, 3000000000000LL);
}

TEST(HliPosition, NotFiniteIsFlagged) {
  EXPECT_TRUE(encode_position(std::nan(""), PositionFormat::scaled_32bit).saturated);
  EXPECT_EQ(encode_position(std::nan(""), PositionFormat::high_res_64bit).raw, 0);
  EXPECT_TRUE(encode_position(INFINITY, PositionFormat::high_res_64bit).saturated);
}

TEST(HliSpeed, RpmToThousandthDegreePerSecond) {
  // 1000 rpm = 6000 deg/s = 6 000 000 * 0.001 deg/s
  EXPECT_EQ(to_hli_speed(1000.0), 6000000);
  EXPECT_EQ(to_hli_speed(-500.0), -3000000);
  EXPECT_EQ(to_hli_speed(1e9), std::numeric_limits<std::int32_t>::max());
}

config::Machine two_channel_machine() {
  config::Machine m;
  m.channels.resize(2);
  m.channels[0].spindles.resize(2);
  m.channels[0].spindles[0].name = "S1";
  m.channels[0].spindles[0].log_axis_nr = 6;
  m.channels[0].spindles[1].name = "S2";
  m.channels[0].spindles[1].log_axis_nr = 7;
  m.channels[1].spindles.resize(2);
  m.channels[1].spindles[0].name = "S3";
  m.channels[1].spindles[0].log_axis_nr = 8;
  m.channels[1].spindles[1].name = "S2";  // the same spindle known to channel 2
  m.channels[1].spindles[1].log_axis_nr = 7;
  return m;
}

TEST(SpindleMap, SharedSpindleHasOneObject) {
  auto map = build_spindle_map(two_channel_machine());
  EXPECT_EQ(map.count, 3u);
  EXPECT_EQ(map.at(1, 0), 0);
  EXPECT_EQ(map.at(1, 1), 1);
  EXPECT_EQ(map.at(2, 0), 2);
  EXPECT_EQ(map.at(2, 1), 1);
  EXPECT_EQ(map.at(2, 2), kNoSpindle);
  EXPECT_EQ(map.at(0, 0), kNoSpindle);
  EXPECT_EQ(map.at(13, 0), kNoSpindle);
  EXPECT_EQ(map.at(1, -1), kNoSpindle);
}

TEST(HliImage, InitialOverridesComeFromSimList) {
  auto m = two_channel_machine();
  m.sim.feed_override_percent = 80;
  m.sim.spindle_override_percent = 90;
  m.ads_32_bit_comp_mode = false;
  auto img = make_hli_image(m);
  EXPECT_DOUBLE_EQ(img.channel[0].feed_override_percent, 80);
  EXPECT_DOUBLE_EQ(img.spindle_control[2].override_percent, 90);
  EXPECT_FALSE(img.ads_32_bit_comp_mode);
  EXPECT_EQ(SpindleStatus{}.mode_bits, spindle_mode::M05);  // a spindle's status starts stopped
}

TEST(HliControl, OverrideCountsOnlyWhenValid) {
  SpindleControl c;
  c.override_percent = 50;
  EXPECT_DOUBLE_EQ(c.effective_override_percent(), 50);
  c.override_valid = false;
  EXPECT_DOUBLE_EQ(c.effective_override_percent(), 100);
}

TEST(HliModeBits, MatchFactsSheet) {
  EXPECT_EQ(spindle_mode::M05, 1u);
  EXPECT_EQ(spindle_mode::M03, 2u);
  EXPECT_EQ(spindle_mode::M04, 4u);
  EXPECT_EQ(spindle_mode::M19, 8u);
  EXPECT_EQ(spindle_mode::HOMING, 32u);
}

}  // namespace
}  // namespace nck::plc
