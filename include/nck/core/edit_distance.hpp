#pragma once
// Did-you-mean suggestions (list keys, PLC scenario actions, command-line
// words): the Levenshtein distance of two words, ignoring ASCII case. Only
// the first kMaxChars characters of each word count, so absurd input stays
// cheap. Setup side (allocates a row).
#include <cstddef>
#include <limits>
#include <string_view>

namespace nck {

inline constexpr std::size_t kEditDistanceMaxChars = 100;

// The distance, or any value >= bound as soon as it is certain to reach
// bound (a caller looking for the nearest word passes its best so far).
std::size_t edit_distance(std::string_view a, std::string_view b,
                          std::size_t bound = std::numeric_limits<std::size_t>::max());

}  // namespace nck
