#pragma once
// Small text helpers of the scenario parser (private to src/sim).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nck/plc/ext_command.hpp"

namespace nck::sim::detail {

struct Token {
  std::string_view text;
  std::uint32_t column = 0;  // 1-based
};

inline char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

inline bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                            [](char x, char y) { return lower(x) == lower(y); });
}

inline bool istarts_with(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && iequals(s.substr(0, prefix.size()), prefix);
}

// Splits a line at blanks; '#' starts a comment; a trailing '\r' is a blank.
inline void tokenize(std::string_view line, std::vector<Token>& out) {
  out.clear();
  const std::size_t hash = line.find('#');
  if (hash != std::string_view::npos) line = line.substr(0, hash);
  auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !blank(line[i])) ++i;
    if (i > start)
      out.push_back(Token{line.substr(start, i - start), static_cast<std::uint32_t>(start + 1)});
  }
}

// A finite decimal number (an optional leading '+' is allowed); the whole
// text must be used.
inline std::optional<double> to_number(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return {};
  double v = 0;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc{} || ptr != s.data() + s.size() || !std::isfinite(v)) return {};
  return v;
}

inline bool valid_spindle_name(std::string_view s) {
  if (s.empty() || s.size() >= plc::kSpindleNameChars || (s[0] != 'S' && s[0] != 's')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
}

// M3 / M03 / M4 / M04 / M5 / M05 / M19 -> 3, 4, 5, 19.
inline std::optional<int> spindle_function(std::string_view s) {
  if (s.size() < 2 || lower(s[0]) != 'm') return {};
  s.remove_prefix(1);
  int n = -1;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
  if (ec != std::errc{} || ptr != s.data() + s.size()) return {};
  if (n == 3 || n == 4 || n == 5 || n == 19) return n;
  return {};
}

// Bytes outside printable ASCII shown as \xNN, at most 40 characters, so
// that a message about garbage stays readable.
inline std::string printable(std::string_view s) {
  std::string out;
  for (char c : s.substr(0, 40)) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out.push_back(c);
    } else {
      constexpr char kHex[] = "0123456789ABCDEF";
      out += "\\x";
      out.push_back(kHex[u >> 4]);
      out.push_back(kHex[u & 0xF]);
    }
  }
  if (s.size() > 40) out += "...";
  return out;
}

}  // namespace nck::sim::detail
