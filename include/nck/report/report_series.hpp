#pragma once
// The report's time series, kept small however long the run: min/max
// envelopes over buckets of cycles (the tool path: timed_path.hpp).
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace nck::app {

// Numbers as short JSON text: at most `decimals` places, trailing zeros cut.
void append_number(std::string& out, double v, int decimals);

// A JSON array of the range's items, each written by item(out, x).
template <class Range, class F>
std::string array_of(const Range& range, F&& item) {
  std::string s = "[";
  bool first = true;
  for (const auto& x : range) {
    if (!first) s += ',';
    first = false;
    item(s, x);
  }
  s += ']';
  return s;
}

// Per cycle, one value per series. A bucket spans `stride` cycles and keeps
// each series' minimum and maximum in the order they occurred; when there
// are kMaxBuckets, neighbours merge and the stride doubles. Drawing the two
// extremes of every bucket reproduces the plot of every cycle at any zoom
// down to one bucket (no aliasing, no solid bands from thinning).
class EnvelopeSeries {
 public:
  static constexpr std::size_t kMaxBuckets = 4096;
  void start(std::size_t series_count, double cycle_s);
  void add(std::uint64_t cycle, std::span<const double> values);
  // {"t":[...],"v":[[...],...]} — two points per bucket (one while stride is 1).
  std::string json(std::span<const int> decimals) const;
  std::size_t buckets() const { return count_; }
  std::uint64_t stride() const { return stride_; }

 private:
  struct Bucket {
    float min = 0, max = 0;
    bool min_first = true;
  };
  void merge_pairs();
  std::vector<Bucket> buckets_;  // bucket k's series s at k * n_ + s
  std::size_t n_ = 0, count_ = 0;
  std::uint64_t stride_ = 1, first_cycle_ = 0;
  std::uint64_t next_start_ = 0;  // the cycle (relative) where the next bucket starts
  bool started_ = false;
  double cycle_s_ = 0.001;
};

}  // namespace nck::app
