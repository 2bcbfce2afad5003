#include "nck/report/report_series.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace nck::app {

namespace {

// |v| · 10^decimals as an integer, when that fits a double's exact integers:
// the report's numbers almost always do, and then writing them is a few
// integer divisions instead of an exact decimal conversion (~500
// instructions each, ~10^5 numbers per report). The last digit may differ
// from exact decimal rounding when v·10^d lies within one ulp of a half:
// invisible in a plot.
bool append_scaled(std::string& out, double v, int decimals) {
  static constexpr double kPow10[] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8};
  if (decimals < 0 || decimals > 8) return false;
  const double scaled = std::fabs(v) * kPow10[decimals];
  if (!(scaled < 1e12)) return false;  // v·10^d then errs by < 10^-4 of a last digit
  auto n = static_cast<std::uint64_t>(std::nearbyint(scaled));  // ties to even, as exact rounding
  if (n == 0) {
    out += '0';
    return true;
  }
  char buf[32];
  char* p = buf + sizeof buf;
  int d = decimals;
  while (d > 0 && n % 10 == 0) {  // trailing zeros of the fraction are not written
    n /= 10;
    --d;
  }
  for (; d > 0; --d, n /= 10) *--p = static_cast<char>('0' + n % 10);
  if (p != buf + sizeof buf) *--p = '.';
  do *--p = static_cast<char>('0' + n % 10);
  while ((n /= 10) != 0);
  if (v < 0) *--p = '-';
  out.append(p, buf + sizeof buf);
  return true;
}

}  // namespace

void append_number(std::string& out, double v, int decimals) {
  if (!std::isfinite(v)) v = 0;
  if (append_scaled(out, v, decimals)) return;
  const std::size_t at = out.size();
  char buf[512];  // a finite double in fixed notation: ≤ 309 digits + decimals
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, std::clamp(decimals, 0, 17));
  out.append(buf, r.ptr);
  if (out.find('.', at) == std::string::npos) return;
  while (out.back() == '0') out.pop_back();
  if (out.back() == '.') out.pop_back();
  if (out.compare(at, std::string::npos, "-0") == 0) out.erase(at, 1);
}

void EnvelopeSeries::start(std::size_t series_count, double cycle_s) {
  n_ = series_count;
  buckets_.clear();
  buckets_.reserve(kMaxBuckets * n_);
  cycle_s_ = cycle_s;
}

void EnvelopeSeries::add(std::uint64_t cycle, std::span<const double> values) {
  if (!started_) {
    first_cycle_ = cycle;
    started_ = true;
  }
  const auto value = [&](std::size_t s) { return static_cast<float>(s < values.size() ? values[s] : 0.0); };
  const std::uint64_t rel = cycle - first_cycle_;
  if (rel >= next_start_) {  // a new bucket (or, after a jump, several)
    while (rel / stride_ >= kMaxBuckets) merge_pairs();
    const std::size_t k = rel / stride_;
    count_ = k + 1;
    next_start_ = (k + 1) * stride_;
    buckets_.resize(count_ * n_, Bucket{});
    Bucket* row = &buckets_[k * n_];
    for (std::size_t s = 0; s < n_; ++s) {
      const float v = value(s);
      row[s] = {v, v, true};
    }
    return;
  }
  // Most cycles: the envelope of the bucket under way widens (one stride in
  // 4,096 buckets is hundreds of cycles). A bucket's series lie side by side;
  // a series without a value keeps its 0, which the bucket holds already.
  Bucket* row = &buckets_[(count_ - 1) * n_];
  const std::size_t n = std::min(n_, values.size());
  for (std::size_t s = 0; s < n; ++s) {
    const auto v = static_cast<float>(values[s]);
    Bucket& x = row[s];
    if (v < x.min) {
      x.min = v;
      x.min_first = false;  // the minimum now comes after the maximum
    }
    if (v > x.max) {
      x.max = v;
      x.min_first = true;
    }
  }
}

void EnvelopeSeries::merge_pairs() {
  const std::size_t merged = (count_ + 1) / 2;
  for (std::size_t out = 0; out < merged; ++out)
    for (std::size_t s = 0; s < n_; ++s) {
      const std::size_t i = 2 * out;
      const Bucket a = buckets_[i * n_ + s];
      if (i + 1 >= count_) {
        buckets_[out * n_ + s] = a;
        continue;
      }
      const Bucket c = buckets_[(i + 1) * n_ + s];
      const bool min_in_a = a.min <= c.min, max_in_a = a.max >= c.max;
      Bucket m{std::min(a.min, c.min), std::max(a.max, c.max), true};
      if (min_in_a && max_in_a) m.min_first = a.min_first;
      else if (!min_in_a && !max_in_a) m.min_first = c.min_first;
      else m.min_first = min_in_a;
      buckets_[out * n_ + s] = m;
    }
  count_ = merged;
  buckets_.resize(count_ * n_);
  stride_ *= 2;
  next_start_ = count_ * stride_;
}

std::string EnvelopeSeries::json(std::span<const int> decimals) const {
  std::string s = "{\"t\":[";
  const bool pairs = stride_ > 1;
  const double bucket_s = static_cast<double>(stride_) * cycle_s_;
  const double t0 = static_cast<double>(first_cycle_) * cycle_s_;
  for (std::size_t k = 0; k < count_; ++k) {
    if (k > 0) s += ',';
    const double t = t0 + static_cast<double>(k) * bucket_s;
    append_number(s, t, 4);
    if (pairs) {
      s += ',';
      append_number(s, t + bucket_s / 2, 4);
    }
  }
  s += "],\"v\":[";
  for (std::size_t i = 0; i < n_; ++i) {
    if (i > 0) s += ',';
    s += '[';
    const int d = i < decimals.size() ? decimals[i] : 3;
    for (std::size_t k = 0; k < count_; ++k) {
      const Bucket& b = buckets_[k * n_ + i];
      if (k > 0) s += ',';
      append_number(s, b.min_first ? b.min : b.max, d);
      if (pairs) {
        s += ',';
        append_number(s, b.min_first ? b.max : b.min, d);
      }
    }
    s += ']';
  }
  s += "]}";
  return s;
}

}  // namespace nck::app
