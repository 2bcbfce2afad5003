// Time by cause's tally of one block, tool or file: its first classes kept
// in place, the rest beside, in the order a plain vector with the same rule
// gives (the hit swapped to the front), which decides the order of equal
// counts in --final and the report.
#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include "nck/output/time_by_cause.hpp"

namespace nck::app {
namespace {

using Entry = CauseTally::Entry;

// The rule on a plain vector, as the ledger kept it before the tally.
void add_to(std::vector<Entry>& t, CauseClass c, std::uint64_t cycles) {
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i].first == c) {
      t[i].second += cycles;
      if (i > 0) std::swap(t[i], t[0]);
      return;
    }
  t.emplace_back(c, cycles);
  std::swap(t.back(), t.front());
}

std::vector<Entry> entries(const CauseTally& t) {
  std::vector<Entry> out;
  for (std::size_t i = 0; i < t.size(); ++i) out.push_back(t[i]);
  return out;
}

TEST(CauseTally, KeepsTheOrderOfAVectorBeyondItsInPlaceClasses) {
  std::mt19937 random(31);
  std::uniform_int_distribution<int> pick(0, 8), cycles(1, 3);
  CauseTally tally;
  std::vector<Entry> expected;
  for (int step = 0; step < 2000; ++step) {
    const int k = pick(random);  // nine classes: more than the tally keeps in place
    const CauseClass c{static_cast<kernel::CycleCause>(1 + k % 4), static_cast<std::int16_t>(k / 4 - 1)};
    const auto n = static_cast<std::uint64_t>(cycles(random));
    tally.add(c, n);
    add_to(expected, c, n);
    ASSERT_EQ(entries(tally), expected) << "step " << step;
  }
  ASSERT_EQ(tally.size(), 9u);
  std::uint64_t sum = 0;
  for (const Entry& e : expected) sum += e.second;
  EXPECT_EQ(tally.cycles(), sum);
  const std::vector<Entry> sorted = tally.sorted();
  for (std::size_t i = 1; i < sorted.size(); ++i) EXPECT_GE(sorted[i - 1].second, sorted[i].second);
}

TEST(CauseTally, EqualCountsKeepTheirOrderWhenSorted) {
  CauseTally tally;
  const CauseClass feed{kernel::CycleCause::feed, -1}, corner{kernel::CycleCause::corner, -1},
      rapid{kernel::CycleCause::rapid, -1};
  tally.add(feed, 2);    // feed
  tally.add(corner, 5);  // corner feed
  tally.add(rapid, 2);   // rapid feed corner
  const std::vector<Entry> sorted = tally.sorted();
  ASSERT_EQ(sorted.size(), 3u);
  EXPECT_EQ(sorted[0].first, corner);
  EXPECT_EQ(sorted[1].first, rapid);  // before feed: its place in the tally
  EXPECT_EQ(sorted[2].first, feed);
}

}  // namespace
}  // namespace nck::app
