#pragma once
// Character-level scanning of one block's text: blanks and comments,
// keywords (case-insensitive), identifiers and unsigned numbers. The parse
// stages walk the block with a Cursor; errors carry the byte position, which
// the source reader maps back to line and column.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nck/core/diagnostic.hpp"

namespace nck::nc::detail {

inline char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 32) : c; }
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_alpha(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
inline bool is_ident_char(char c) { return is_alpha(c) || is_digit(c) || c == '_'; }
bool iequals(std::string_view a, std::string_view b);
std::string to_upper(std::string_view s);

struct ParseError {
  ErrorId id{};
  std::uint32_t pos = 0;  // byte offset in the block text
  std::string message;
};

// First error of a block wins; warnings are collected.
struct ErrorSlot {
  std::optional<ParseError> error;
  std::vector<ParseError> warnings;
  bool fail(ErrorId id, std::size_t pos, std::string msg) {
    if (!error) error = ParseError{id, static_cast<std::uint32_t>(pos), std::move(msg)};
    return false;
  }
  void warn(ErrorId id, std::size_t pos, std::string msg) {
    warnings.push_back(ParseError{id, static_cast<std::uint32_t>(pos), std::move(msg)});
  }
  bool failed() const { return error.has_value(); }
  void clear() { error.reset(); warnings.clear(); }
};

struct Cursor {
  std::string_view s;
  std::size_t pos = 0;

  bool at_end() const { return pos >= s.size(); }
  char peek(std::size_t k = 0) const { return pos + k < s.size() ? s[pos + k] : '\0'; }
  char get() { return pos < s.size() ? s[pos++] : '\0'; }
  // Blanks, ( nested ) comments and ; comments. An unclosed ( runs to the
  // end of the block, as the ISG manual allows.
  void skip_blanks();
  // Blanks only (no comments): inside [ ] a ( is not a comment opener either.
  void skip_spaces() {
    while (pos < s.size() && (s[pos] == ' ' || s[pos] == '\t' || s[pos] == '\r')) ++pos;
  }
  // Nothing but blanks/comments left?
  bool rest_empty() {
    skip_blanks();
    return at_end();
  }
  bool match(char c) {
    if (peek() != c) return false;
    ++pos;
    return true;
  }
  // Case-insensitive keyword that is not followed by an identifier character.
  bool match_keyword(std::string_view kw);
  // Case-insensitive prefix (no boundary check).
  bool match_prefix(std::string_view kw);
  bool peek_keyword(std::string_view kw) const;
  // [A-Za-z_][A-Za-z0-9_]* ; empty if none.
  std::string_view read_ident();
  // Unsigned decimal: 12, 12.5, .5, 12. ; false (pos unchanged) if none.
  bool read_number(double& out);
};

}  // namespace nck::nc::detail
