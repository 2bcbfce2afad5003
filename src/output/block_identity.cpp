#include "nck/output/block_identity.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <functional>
#include <unordered_map>

namespace nck::app {
namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// The section a `%` header opens: the name of `%L name`, "" for a program.
std::string section_of(const std::string& header) {
  if (header.size() < 2 || std::toupper(static_cast<unsigned char>(header[1])) != 'L') return {};
  if (header.size() > 2 && header[2] != ' ') return {};  // `%LATHE` names a main program
  std::string name = header.size() > 3 ? header.substr(3) : std::string();
  for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

// Reads the file line by line: f(line number, identity text, section);
// one buffer for every line's text, so a long program allocates nothing per line.
template <class F>
bool each_line(const std::string& path, F&& f) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::string raw, text, section;
  for (std::uint32_t n = 1; std::getline(in, raw); ++n) {
    identity_text(raw, text);
    if (!text.empty() && text[0] == '%') section = section_of(text);
    if (!f(n, std::string_view(text), section)) break;
  }
  return true;
}

// Hashes and compares std::string and std::string_view alike (a lookup
// by the reading buffer's view makes no string).
struct TextHash {
  using is_transparent = void;
  std::size_t operator()(std::string_view v) const { return std::hash<std::string_view>{}(v); }
};

}  // namespace

void identity_text(std::string_view line, std::string& out) {
  line = line.substr(0, std::min(line.find(';'), line.size()));
  out.clear();
  for (char c : line) {
    if (!blank(c)) out += c;
    else if (!out.empty() && out.back() != ' ') out += ' ';
  }
  if (!out.empty() && out.back() == ' ') out.pop_back();
}

std::string identity_text(std::string_view line) {
  std::string out;
  identity_text(line, out);
  return out;
}

std::vector<BlockIdentity> block_identities(const std::string& path, const std::vector<std::uint32_t>& lines) {
  std::vector<BlockIdentity> ids(lines.size());
  std::unordered_map<std::uint32_t, std::vector<std::size_t>> wanted;  // line -> indexes into ids
  std::uint32_t last = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) wanted[lines[i]].push_back(i), last = std::max(last, lines[i]);
  // first read: the text and section of each line asked for
  const bool readable = each_line(path, [&](std::uint32_t n, std::string_view text, const std::string& section) {
    if (const auto it = wanted.find(n); it != wanted.end())
      for (std::size_t i : it->second) ids[i].text = text, ids[i].section = section;
    return n < last;
  });
  if (!readable) return ids;
  // second read: how often each of those texts came before, in its section
  // (text -> section -> lines of it so far)
  std::unordered_map<std::string, std::unordered_map<std::string, std::uint32_t>, TextHash, std::equal_to<>> seen;
  for (const BlockIdentity& id : ids) seen[id.text].emplace(id.section, 0);
  each_line(path, [&](std::uint32_t n, std::string_view text, const std::string& section) {
    const auto by_text = seen.find(text);
    if (by_text == seen.end()) return true;
    const auto counted = by_text->second.find(section);
    if (counted == by_text->second.end()) return true;
    ++counted->second;
    if (const auto it = wanted.find(n); it != wanted.end())
      for (std::size_t i : it->second) ids[i].pass = counted->second;
    return n < last;
  });
  return ids;
}

}  // namespace nck::app
