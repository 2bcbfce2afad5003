#pragma once
// n / d, remembered for the last n and d. A division is among the longest
// steps on the cycle's path (its latency stalls what depends on it), and a
// machine at a steady state divides the same numbers cycle after cycle.
// Compared bit for bit, so the result is always the division's own (signed
// zeros and NaN included). // rt
#include <bit>
#include <cstdint>

namespace nck {

class KeptQuotient {
 public:
  double divide(double n, double d) noexcept {
    const auto n_bits = std::bit_cast<std::uint64_t>(n), d_bits = std::bit_cast<std::uint64_t>(d);
    if (n_bits != n_bits_ || d_bits != d_bits_) {
      n_bits_ = n_bits;
      d_bits_ = d_bits;
      q_ = n / d;
    }
    return q_;
  }

 private:
  std::uint64_t n_bits_ = 0, d_bits_ = std::bit_cast<std::uint64_t>(1.0);  // 0 / 1
  double q_ = 0;
};

}  // namespace nck
