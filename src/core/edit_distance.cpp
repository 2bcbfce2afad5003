#include "nck/core/edit_distance.hpp"

#include <algorithm>
#include <vector>

namespace nck {
namespace {

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b, std::size_t bound) {
  a = a.substr(0, kEditDistanceMaxChars);
  b = b.substr(0, kEditDistanceMaxChars);
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    std::size_t row_min = row[0];
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (lower(a[i - 1]) == lower(b[j - 1]) ? 0u : 1u)});
      row_min = std::min(row_min, row[j]);
      diag = up;
    }
    // A row's minimum never falls again further down.
    if (row_min >= bound) return bound;
  }
  return row[b.size()];
}

}  // namespace nck
