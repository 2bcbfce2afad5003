#include "nck/output/block_identity.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
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

// Reads the file line by line: f(line number, identity text, section).
template <class F>
bool each_line(const std::string& path, F&& f) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::string raw, section;
  for (std::uint32_t n = 1; std::getline(in, raw); ++n) {
    const std::string text = identity_text(raw);
    if (!text.empty() && text[0] == '%') section = section_of(text);
    if (!f(n, text, section)) break;
  }
  return true;
}

std::string key_of(const std::string& section, const std::string& text) { return section + '\n' + text; }

}  // namespace

std::string identity_text(std::string_view line) {
  line = line.substr(0, std::min(line.find(';'), line.size()));
  std::string out;
  out.reserve(line.size());
  for (char c : line) {
    if (!blank(c)) out += c;
    else if (!out.empty() && out.back() != ' ') out += ' ';
  }
  if (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

std::vector<BlockIdentity> block_identities(const std::string& path, const std::vector<std::uint32_t>& lines) {
  std::vector<BlockIdentity> ids(lines.size());
  std::unordered_map<std::uint32_t, std::vector<std::size_t>> wanted;  // line -> indexes into ids
  std::uint32_t last = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) wanted[lines[i]].push_back(i), last = std::max(last, lines[i]);
  // first read: the text and section of each line asked for
  const bool readable = each_line(path, [&](std::uint32_t n, const std::string& text, const std::string& section) {
    if (const auto it = wanted.find(n); it != wanted.end())
      for (std::size_t i : it->second) ids[i].text = text, ids[i].section = section;
    return n < last;
  });
  if (!readable) return ids;
  // second read: how often each of those texts came before, in its section
  std::unordered_map<std::string, std::uint32_t> seen;
  for (const BlockIdentity& id : ids) seen.emplace(key_of(id.section, id.text), 0);
  each_line(path, [&](std::uint32_t n, const std::string& text, const std::string& section) {
    const auto counted = seen.find(key_of(section, text));
    if (counted == seen.end()) return true;
    ++counted->second;
    if (const auto it = wanted.find(n); it != wanted.end())
      for (std::size_t i : it->second) ids[i].pass = counted->second;
    return n < last;
  });
  return ids;
}

}  // namespace nck::app
