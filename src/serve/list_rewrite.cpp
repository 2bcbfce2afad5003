#include "nck/serve/list_rewrite.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <system_error>
#include <vector>

#include <fmt/format.h>

namespace nck::app::serve {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool blank(char c) { return c == ' ' || c == '\t'; }

// The line with its value token replaced; the blanks after the value give
// way (down to one) so that a remark keeps its column.
std::string with_value(std::string_view line, std::size_t value_at, std::size_t value_end, const std::string& value) {
  std::string out(line.substr(0, value_at));
  out += value;
  std::size_t spaces = 0;
  while (value_end + spaces < line.size() && line[value_end + spaces] == ' ') ++spaces;
  if (spaces > 0 && value_end + spaces < line.size()) {  // a remark in a column
    const std::size_t old_width = value_end - value_at + spaces;
    out.append(old_width > value.size() + 1 ? old_width - value.size() : 1, ' ');
    out += line.substr(value_end + spaces);
  } else {
    out += line.substr(value_end);
  }
  return out;
}

}  // namespace

ListFingerprint fingerprint_of(std::string_view bytes) noexcept {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return {h, bytes.size()};
}

std::optional<ListFingerprint> fingerprint_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return fingerprint_of(s.str());
}

std::string rewrite_list(std::string_view text, const std::map<std::string, std::string>& values) {
  std::string out;
  std::set<std::string> done;
  std::size_t ende_at = std::string::npos;  // where "Ende" starts in out
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t nl = text.find('\n', pos);
    const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
    std::string_view line = text.substr(pos, end - pos);
    const bool cr = !line.empty() && line.back() == '\r';
    if (cr) line.remove_suffix(1);
    std::size_t k = 0;
    while (k < line.size() && blank(line[k])) ++k;
    std::size_t key_end = k;
    while (key_end < line.size() && !blank(line[key_end])) ++key_end;
    const std::string key = lower(line.substr(k, key_end - k));
    std::size_t v = key_end;
    while (v < line.size() && blank(line[v])) ++v;
    std::size_t v_end = v;
    while (v_end < line.size() && !blank(line[v_end])) ++v_end;
    const auto it = values.find(key);
    if (key == "ende" && ende_at == std::string::npos) ende_at = out.size();
    if (it != values.end() && v < v_end && !done.contains(key)) {
      out += with_value(line, v, v_end, it->second);
      done.insert(key);
    } else {
      out += line;
    }
    if (cr) out += '\r';
    if (nl != std::string_view::npos) out += '\n';
    pos = end + 1;
  }
  std::string added;
  for (const auto& [key, value] : values)
    if (!done.contains(key)) added += fmt::format("{:<28} {}\n", key, value);
  if (added.empty()) return out;
  if (ende_at != std::string::npos) return out.insert(ende_at, added);
  if (!out.empty() && out.back() != '\n') out += '\n';
  return out + added;
}

std::optional<std::string> replace_file_with_backup(const fs::path& file, std::string_view text) {
  const fs::path tmp = fs::path(file).concat(".tmp");
  const fs::path bak = fs::path(file).concat(".bak");
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return fmt::format("cannot write {}", tmp.string());
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out) {
      out.close();
      std::error_code ec;
      fs::remove(tmp, ec);
      return fmt::format("cannot write {} (disk full?)", tmp.string());
    }
  }
  std::error_code ec;
  fs::copy_file(file, bak, fs::copy_options::overwrite_existing, ec);
  if (ec) {
    fs::remove(tmp, ec);
    return fmt::format("cannot keep the old file as {}", bak.string());
  }
  fs::rename(tmp, file, ec);  // atomic on one file system: the old or the new file, never half
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    return fmt::format("cannot replace {}: {}", file.string(), ec.message());
  }
  return std::nullopt;
}

}  // namespace nck::app::serve
