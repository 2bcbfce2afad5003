#include "block_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <vector>

namespace nck::app {
namespace {

using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

std::string text_of(const json& r, const char* key) {
  return r.is_object() && r.contains(key) && r[key].is_string() ? r[key].get<std::string>() : std::string();
}

double round_us(double s) { return std::round(s * 1e6) / 1e6; }

// One block of one side.
struct Entry {
  std::string identity;  // file, sub, text, pass (or file and line without an identity)
  std::string by_n;      // file, sub and N number; "" without N
  std::string shown;     // how a row names it
  std::string text;
  json line, n;
  double time_s = 0;
};

Entry entry_of(const json& r, const std::string& main_file) {
  Entry e;
  const std::string path = text_of(r, "file");
  const std::string file = path.empty() || path == main_file ? std::string()
                                                              : std::filesystem::path(path).filename().string();
  const std::string sub = text_of(r, "sub");
  e.text = text_of(r, "text");
  e.line = r.is_object() && r.contains("line") ? r["line"] : json();
  e.n = r.is_object() && r.contains("n") ? r["n"] : json();
  e.time_s = r.is_object() && r.contains("time_s") && r["time_s"].is_number() ? r["time_s"].get<double>() : 0;
  const json pass = r.is_object() && r.contains("pass") ? r["pass"] : json();
  if (e.text.empty() || !pass.is_number_unsigned() || pass.get<std::uint32_t>() == 0) {
    // no identity: by line, as nck diff matched before (main program: "line 12")
    e.shown = file.empty() ? "line " + e.line.dump() : file + ":" + e.line.dump();
    e.identity = "\x01" + e.shown;
    return e;
  }
  const std::uint32_t p = pass.get<std::uint32_t>();
  const std::string where = file.empty() ? sub : sub.empty() ? file : file + " " + sub;
  e.identity = fmt::format("{}\n{}\n{}\n{}", file, sub, e.text, p);
  e.shown = fmt::format("{}{}{}", where.empty() ? "" : where + ": ", e.text, p > 1 ? fmt::format(" #{}", p) : "");
  if (e.n.is_number_integer()) e.by_n = fmt::format("{}\n{}\n{}", file, sub, e.n.dump());
  return e;
}

// One side's blocks by identity; rows of one identity (two files of one
// name in two folders) add up.
std::vector<Entry> entries_of(const json& rows, const std::string& main_file) {
  std::vector<Entry> out;
  std::map<std::string, std::size_t> index;
  if (!rows.is_array()) return out;
  for (const json& r : rows) {
    Entry e = entry_of(r, main_file);
    const auto [it, added] = index.try_emplace(e.identity, out.size());
    if (added) out.push_back(std::move(e));
    else out[it->second].time_s += e.time_s;
  }
  return out;
}

using Pair = std::pair<std::optional<std::size_t>, std::optional<std::size_t>>;

// The blocks of A and B with one identity; then, among those left, the
// ones whose N number is one block's on each side.
std::vector<Pair> pair_up(const std::vector<Entry>& a, const std::vector<Entry>& b) {
  std::map<std::string, std::size_t> b_of;
  for (std::size_t j = 0; j < b.size(); ++j) b_of[b[j].identity] = j;
  std::vector<Pair> pairs;
  std::vector<bool> b_taken(b.size(), false);
  std::vector<std::size_t> a_left;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto it = b_of.find(a[i].identity);
    if (it == b_of.end()) {
      a_left.push_back(i);
      continue;
    }
    pairs.push_back({i, it->second});
    b_taken[it->second] = true;
  }
  // N number -> the blocks left with it (more than one on a side: none pairs)
  std::map<std::string, std::pair<std::vector<std::size_t>, std::vector<std::size_t>>> by_n;
  for (std::size_t i : a_left)
    if (!a[i].by_n.empty()) by_n[a[i].by_n].first.push_back(i);
  for (std::size_t j = 0; j < b.size(); ++j)
    if (!b_taken[j] && !b[j].by_n.empty()) by_n[b[j].by_n].second.push_back(j);
  std::vector<bool> a_paired(a.size(), false);
  for (const auto& [n, sides] : by_n) {
    if (sides.first.size() != 1 || sides.second.size() != 1) continue;
    pairs.push_back({sides.first[0], sides.second[0]});
    a_paired[sides.first[0]] = true;
    b_taken[sides.second[0]] = true;
  }
  for (std::size_t i : a_left)
    if (!a_paired[i]) pairs.push_back({i, std::nullopt});
  for (std::size_t j = 0; j < b.size(); ++j)
    if (!b_taken[j]) pairs.push_back({std::nullopt, j});
  return pairs;
}

ojson row_of(const Pair& p, const std::vector<Entry>& a, const std::vector<Entry>& b) {
  const Entry* ea = p.first ? &a[*p.first] : nullptr;
  const Entry* eb = p.second ? &b[*p.second] : nullptr;
  const Entry& e = ea ? *ea : *eb;
  const double da = ea ? ea->time_s : 0, db = eb ? eb->time_s : 0;
  ojson r{{"key", e.shown}, {"n", ojson::parse(e.n.dump())}, {"text", e.text},
          {"line_a", ea ? ojson::parse(ea->line.dump()) : ojson(nullptr)},
          {"line_b", eb ? ojson::parse(eb->line.dump()) : ojson(nullptr)}};
  if (ea && eb && ea->text != eb->text) r["text_b"] = eb->text;
  r["a_s"] = ea ? ojson(round_us(da)) : ojson(nullptr);
  r["b_s"] = eb ? ojson(round_us(db)) : ojson(nullptr);
  r["delta_s"] = round_us(db - da);
  return r;
}

}  // namespace

ojson compare_blocks(const json& rows_a, const std::string& main_a, const json& rows_b, const std::string& main_b) {
  const std::vector<Entry> a = entries_of(rows_a, main_a), b = entries_of(rows_b, main_b);
  std::vector<ojson> rows;
  for (const Pair& p : pair_up(a, b)) rows.push_back(row_of(p, a, b));
  // the largest change first; equal changes by name, so the order is the same every time
  std::stable_sort(rows.begin(), rows.end(), [](const ojson& x, const ojson& y) {
    const double dx = std::abs(x["delta_s"].get<double>()), dy = std::abs(y["delta_s"].get<double>());
    return dx != dy ? dx > dy : x["key"].get<std::string>() < y["key"].get<std::string>();
  });
  ojson out = ojson::array();
  for (ojson& r : rows) out.push_back(std::move(r));
  return out;
}

}  // namespace nck::app
