#include "lexer.hpp"

#include <charconv>

namespace nck::nc::detail {

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (upper(a[i]) != upper(b[i])) return false;
  return true;
}

std::string to_upper(std::string_view s) {
  std::string r(s);
  for (auto& c : r) c = upper(c);
  return r;
}

void Cursor::skip_blanks() {
  while (pos < s.size()) {
    char c = s[pos];
    if (c == ' ' || c == '\t' || c == '\r') {
      ++pos;
    } else if (c == ';') {
      pos = s.size();
    } else if (c == '(') {
      int depth = 0;
      while (pos < s.size()) {
        if (s[pos] == '(') ++depth;
        else if (s[pos] == ')' && --depth == 0) { ++pos; break; }
        ++pos;
      }
    } else {
      break;
    }
  }
}

bool Cursor::peek_keyword(std::string_view kw) const {
  if (s.size() - pos < kw.size() || pos > s.size()) return false;
  for (std::size_t i = 0; i < kw.size(); ++i)
    if (upper(s[pos + i]) != kw[i]) return false;
  std::size_t end = pos + kw.size();
  return end >= s.size() || !is_ident_char(s[end]);
}

bool Cursor::match_keyword(std::string_view kw) {
  if (!peek_keyword(kw)) return false;
  pos += kw.size();
  return true;
}

bool Cursor::match_prefix(std::string_view kw) {
  if (pos > s.size() || s.size() - pos < kw.size()) return false;
  for (std::size_t i = 0; i < kw.size(); ++i)
    if (upper(s[pos + i]) != kw[i]) return false;
  pos += kw.size();
  return true;
}

std::string_view Cursor::read_ident() {
  std::size_t b = pos;
  if (pos < s.size() && (is_alpha(s[pos]) || s[pos] == '_')) {
    ++pos;
    while (pos < s.size() && is_ident_char(s[pos])) ++pos;
  }
  return s.substr(b, pos - b);
}

bool Cursor::read_number(double& out) {
  std::size_t b = pos, p = pos;
  bool digits = false;
  while (p < s.size() && is_digit(s[p])) { ++p; digits = true; }
  if (p < s.size() && s[p] == '.') {
    ++p;
    while (p < s.size() && is_digit(s[p])) { ++p; digits = true; }
  }
  if (!digits) return false;
  // Optional exponent only when it is unambiguous: E followed by a sign or digit
  // and not an address letter use (1E3 is read as 1000).
  if (p + 1 < s.size() && (s[p] == 'E' || s[p] == 'e') &&
      (is_digit(s[p + 1]) || ((s[p + 1] == '+' || s[p + 1] == '-') && p + 2 < s.size() &&
                              is_digit(s[p + 2])))) {
    std::size_t q = p + 1;
    if (s[q] == '+' || s[q] == '-') ++q;
    while (q < s.size() && is_digit(s[q])) ++q;
    p = q;
  }
  const char* first = s.data() + b;
  const char* last = s.data() + p;
  // from_chars does not accept a trailing "12." form's dot? It does; but not ".5" leading dot? It does.
  auto r = std::from_chars(first, last, out);
  if (r.ec != std::errc{}) {
    out = 0;
    if (r.ec == std::errc::result_out_of_range) return false;
  }
  pos = p;
  return true;
}

}  // namespace nck::nc::detail
