// The report's data reduction: min/max envelopes and the thinned tool path.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <numbers>

#include "nck/report/report_series.hpp"

namespace nck::app {
namespace {

using nlohmann::json;

TEST(ReportNumbers, ShortestTextWithinTheDecimals) {
  std::string s;
  append_number(s, 12.5000, 4);
  s += ',';
  append_number(s, -0.00001, 4);
  s += ',';
  append_number(s, 3.0, 2);
  s += ',';
  append_number(s, 0.123456, 3);
  EXPECT_EQ(s, "12.5,0,3,0.123");
}

// The fast integer path against exact decimal rounding: the same text but
// for the last digit next to a rounding tie, and big numbers exactly.
TEST(ReportNumbers, AgreeWithExactRoundingAcrossMagnitudes) {
  std::uint64_t seed = 12345;
  const auto next = [&] { return (seed = seed * 6364136223846793005ull + 1442695040888963407ull) >> 11; };
  int differing = 0;
  for (int i = 0; i < 20000; ++i) {
    const int decimals = static_cast<int>(next() % 9);
    const double mag = std::pow(10.0, static_cast<double>(next() % 14) - 4);
    const double v = (static_cast<double>(next()) / 9007199254740992.0 - 0.5) * mag;
    std::string fast;
    append_number(fast, v, decimals);
    char buf[512];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
    const double exact = std::strtod(std::string(buf, r.ptr).c_str(), nullptr);
    const double got = std::strtod(fast.c_str(), nullptr);
    ASSERT_LE(std::fabs(got - exact), std::pow(10.0, -decimals) + 1e-15 * std::fabs(v)) << v << " " << decimals;
    if (got != exact) ++differing;
  }
  EXPECT_LE(differing, 3);  // a tie within 10^-4 of a last digit is rare
  std::string big;
  append_number(big, -1.25e17, 2);
  EXPECT_EQ(big, "-125000000000000000");
}

TEST(EnvelopeSeries, EveryCycleWhileShort) {
  EnvelopeSeries e;
  e.start(1, 0.001);
  for (std::uint64_t c = 0; c < 10; ++c) e.add(c, std::array{double(c)});
  const int dec[] = {3};
  const json j = json::parse(e.json(dec));
  EXPECT_EQ(j["t"].size(), 10u);
  EXPECT_EQ(j["v"][0][9], 9);
  EXPECT_EQ(j["t"][9], 0.009);
}

// A 100 Hz square wave over 1,000,000 cycles of 1 ms: thinning to every
// 256th cycle would alias it to a constant; the envelope keeps -1 and +1
// in every bucket and stays within kMaxBuckets.
TEST(EnvelopeSeries, KeepsMinAndMaxOfLongRunsInBoundedSize) {
  EnvelopeSeries e;
  e.start(2, 0.001);
  const std::uint64_t n = 1'000'000;
  for (std::uint64_t c = 0; c < n; ++c) {
    const double square = (c / 5) % 2 == 0 ? 1.0 : -1.0;
    const double ramp = double(c);
    e.add(c, std::array{square, ramp});
  }
  EXPECT_LE(e.buckets(), EnvelopeSeries::kMaxBuckets);
  EXPECT_EQ(e.stride(), 256u);  // 1e6 / 4096 -> the next power of two
  const int dec[] = {3, 0};
  const json j = json::parse(e.json(dec));
  const auto& sq = j["v"][0];
  ASSERT_EQ(sq.size(), 2 * e.buckets());
  for (std::size_t k = 0; k < e.buckets(); ++k) {
    EXPECT_EQ(std::min(sq[2 * k].get<double>(), sq[2 * k + 1].get<double>()), -1) << k;
    EXPECT_EQ(std::max(sq[2 * k].get<double>(), sq[2 * k + 1].get<double>()), 1) << k;
  }
  // a rising ramp: each bucket's minimum comes first, at the bucket's first cycle
  const auto& ramp = j["v"][1];
  EXPECT_EQ(ramp[0], 0);
  EXPECT_EQ(ramp[1], 255);
  EXPECT_EQ(ramp[2], 256);
  EXPECT_EQ(ramp[ramp.size() - 1], n - 1);
  EXPECT_NEAR(j["t"][2].get<double>(), 0.256, 1e-9);
}

}  // namespace
}  // namespace nck::app
