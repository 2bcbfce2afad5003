#include "nck/config/list_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <iterator>

namespace nck::config {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && (is_blank(s.front()) || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (is_blank(s.back()) || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

bool is_key_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '[' || c == ']';
}

bool has_control_bytes(std::string_view s) {
  return std::any_of(s.begin(), s.end(), [](char c) {
    auto u = static_cast<unsigned char>(c);
    return (u < 0x20 && c != '\t' && c != '\r') || u == 0x7f;
  });
}

// Cuts a trailing remark: '#' or '(' that follows a blank starts it.
std::string_view strip_remark(std::string_view v) {
  for (std::size_t i = 1; i < v.size(); ++i)
    if ((v[i] == '#' || v[i] == '(') && is_blank(v[i - 1])) return trim(v.substr(0, i));
  if (!v.empty() && (v[0] == '#' || v[0] == '(')) return {};
  return v;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Classifies one raw line; returns false when it carries no key/value pair.
bool parse_line(std::string_view raw, std::uint32_t line_no, const std::string& file,
                ListText& out, Diagnostics& diags, bool& end_seen) {
  SourceLoc loc{file, line_no, 0};
  if (raw.size() > kMaxListLineLength) {
    diags.add(ErrorId::ConfigBadLine, loc,
              fmt::format("line has {} characters (at most {}); line ignored", raw.size(),
                          kMaxListLineLength));
    return false;
  }
  if (has_control_bytes(raw)) {
    diags.add(ErrorId::ConfigBadLine, loc, "line contains binary data; line ignored");
    return false;
  }
  std::string_view s = trim(raw);
  if (s.empty() || s.front() == '#' || s.front() == '(' || s.front() == ';') return false;
  std::size_t key_end = 0;
  while (key_end < s.size() && !is_blank(s[key_end])) ++key_end;
  std::string_view key = s.substr(0, key_end);
  if (lower(key) == "ende" || lower(key) == "end") {
    end_seen = true;
    return false;
  }
  bool key_ok = (std::isalpha(static_cast<unsigned char>(key.front())) || key.front() == '_') &&
                std::all_of(key.begin(), key.end(), is_key_char);
  if (!key_ok) {
    diags.add(ErrorId::ConfigBadLine, loc,
              fmt::format("'{}' is not a key (letters, digits, '_', '.', '[n]'); line ignored",
                          key.substr(0, 40)));
    return false;
  }
  out.lines.push_back(ListLine{lower(key), std::string(strip_remark(trim(s.substr(key_end)))),
                               line_no});
  return true;
}

// Lines after 'Ende' are ignored, as on the control; a forgotten 'Ende' in the
// middle of a list silently drops the rest, so one warning names the first.
void warn_text_after_end(std::string_view text, std::size_t pos, std::uint32_t end_line_no,
                         const std::string& file, Diagnostics& diags) {
  for (std::uint32_t line_no = end_line_no + 1; pos < text.size(); ++line_no) {
    std::size_t nl = text.find('\n', pos);
    std::string_view s = trim(text.substr(pos, nl == std::string_view::npos ? text.size() - pos : nl - pos));
    if (!s.empty() && s.front() != '#' && s.front() != '(' && s.front() != ';') {
      diags.add(ErrorId::ConfigTextAfterEnd, SourceLoc{file, line_no, 0},
                fmt::format("'{}' stands after the Ende line {} and is ignored", s.substr(0, 40), end_line_no));
      return;
    }
    if (nl == std::string_view::npos) return;
    pos = nl + 1;
  }
}

}  // namespace

ListText read_list_text(std::string_view text, std::string file, Diagnostics& diags) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a UTF-8 byte-order mark
  ListText out;
  out.file = std::move(file);
  Diagnostics local;
  std::uint32_t line_no = 0;
  bool end_seen = false;
  std::size_t pos = 0;
  while (pos <= text.size() && !end_seen) {
    std::size_t nl = text.find('\n', pos);
    std::string_view raw = text.substr(pos, nl == std::string_view::npos ? text.size() - pos : nl - pos);
    ++line_no;
    parse_line(raw, line_no, out.file, out, local, end_seen);
    if (local.items().size() >= kMaxDiagnosticsPerList) {
      local.add(ErrorId::ConfigTooManyErrors, SourceLoc{out.file, line_no, 0},
                fmt::format("{} errors so far; the rest of the file is ignored", local.items().size()));
      break;
    }
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    if (nl == std::string_view::npos) break;
  }
  if (end_seen) warn_text_after_end(text, pos, line_no, out.file, local);
  if (out.lines.empty() && local.empty())  // a truncated or wrong file, most likely: say so
    local.add(ErrorId::ConfigEmptyList, SourceLoc{out.file, 1, 0},
              "the list file has no parameter lines; every parameter keeps its default");
  diags.append(local);
  return out;
}

std::optional<ListText> read_list_file(const std::filesystem::path& path,
                                       const std::string& display_name, Diagnostics& diags,
                                       SourceLoc referenced_from) {
  if (referenced_from.file.empty()) referenced_from.file = display_name;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    diags.add(ErrorId::ConfigFileUnreadable, referenced_from,
              fmt::format("list file '{}' does not exist or is not a file", display_name));
    return std::nullopt;
  }
  auto size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxListFileBytes) {
    diags.add(ErrorId::ConfigFileUnreadable, referenced_from,
              fmt::format("list file '{}' cannot be read or is larger than {} MB", display_name,
                          kMaxListFileBytes >> 20));
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diags.add(ErrorId::ConfigFileUnreadable, referenced_from,
              fmt::format("list file '{}' cannot be opened", display_name));
    return std::nullopt;
  }
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return read_list_text(text, display_name, diags);
}

std::optional<double> parse_number(std::string_view t) {
  if (t.empty() || t.size() > 64) return std::nullopt;
  bool neg = false;
  if (t.front() == '+' || t.front() == '-') {
    neg = t.front() == '-';
    t.remove_prefix(1);
  }
  if (t.empty()) return std::nullopt;
  if (t.size() > 2 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) {
    std::uint64_t v = 0;
    auto r = std::from_chars(t.data() + 2, t.data() + t.size(), v, 16);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size()) return std::nullopt;
    double d = static_cast<double>(v);
    return neg ? -d : d;
  }
  if (!std::isdigit(static_cast<unsigned char>(t.front())) && t.front() != '.') return std::nullopt;
  double v = 0;
  auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v)) return std::nullopt;
  return neg ? -v : v;
}

std::vector<std::string_view> value_tokens(std::string_view value) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < value.size()) {
    while (i < value.size() && (is_blank(value[i]) || value[i] == '|')) ++i;
    std::size_t start = i;
    while (i < value.size() && !is_blank(value[i]) && value[i] != '|') ++i;
    if (i > start) out.push_back(value.substr(start, i - start));
  }
  return out;
}

}  // namespace nck::config
