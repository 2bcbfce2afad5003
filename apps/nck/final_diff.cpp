#include "final_diff.hpp"

#include "block_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

namespace nck::app {
namespace {

using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

Diagnostic bad(ErrorId id, const std::string& file, std::uint32_t line, std::string text) {
  return make_diagnostic(id, SourceLoc{file, line, 0}, std::move(text));
}

// The 1-based line of a byte offset of the text.
std::uint32_t line_of(const std::string& text, std::size_t byte) {
  const auto end = text.begin() + static_cast<std::ptrdiff_t>(std::min(byte, text.size()));
  return static_cast<std::uint32_t>(1 + std::count(text.begin(), end, '\n'));
}

double number_or(const json& j, const char* key, double fallback = 0) {
  return j.is_object() && j.contains(key) && j[key].is_number() ? j[key].get<double>() : fallback;
}

std::string string_or(const json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string();
}

double round_us(double s) { return std::round(s * 1e6) / 1e6; }

// key -> time of one side's rows (summed where a key repeats).
using Times = std::map<std::string, double>;

Times times_of(const json& rows, const std::function<std::string(const json&)>& key) {
  Times t;
  if (rows.is_array())
    for (const json& r : rows) t[key(r)] += number_or(r, "time_s");
  return t;
}

// Rows {key, a_s, b_s, delta_s}, the largest change first (then by key).
ojson compare(const Times& a, const Times& b) {
  std::map<std::string, std::pair<const double*, const double*>> both;
  for (const auto& [k, v] : a) both[k].first = &v;
  for (const auto& [k, v] : b) both[k].second = &v;
  std::vector<std::pair<double, ojson>> rows;
  for (const auto& [k, v] : both) {
    const double da = v.first ? *v.first : 0, db = v.second ? *v.second : 0;
    rows.emplace_back(std::abs(db - da),
                      ojson{{"key", k}, {"a_s", v.first ? ojson(round_us(da)) : ojson(nullptr)},
                            {"b_s", v.second ? ojson(round_us(db)) : ojson(nullptr)}, {"delta_s", round_us(db - da)}});
  }
  std::stable_sort(rows.begin(), rows.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  ojson out = ojson::array();
  for (auto& [d, r] : rows) out.push_back(std::move(r));
  return out;
}

std::string file_key(const json& r) {
  if (r.is_object() && r.value("main", false)) return "(main program)";
  const std::string f = string_or(r, "file");
  return f.empty() ? "(main program)" : std::filesystem::path(f).filename().string();
}

// The channel's main program file, as its subroutine rows name it.
std::string main_file(const json& ch) {
  if (ch.is_object() && ch.contains("subroutines") && ch["subroutines"].is_array())
    for (const json& r : ch["subroutines"])
      if (r.is_object() && r.value("main", false)) return string_or(r, "file");
  return {};
}

const json& channel_of(const json& doc, std::size_t i) {
  static const json none = json::object();
  const json& chs = doc["time_by_cause"]["channels"];
  return i < chs.size() ? chs[i] : none;
}

}  // namespace

std::expected<json, Diagnostic> check_final(json doc, const std::string& what) {
  if (!doc.is_object() || !doc.contains("time") || !doc["time"].is_number())
    return std::unexpected(bad(ErrorId::AppDiffNotFinal, what, 0, "no final state of nck run --final: it has no \"time\""));
  if (!doc.contains("format") || !doc["format"].is_number_integer())
    return std::unexpected(bad(ErrorId::AppDiffFormat, what, 0,
                               "a final state without \"format\" (written before nck 0.2); nck diff compares format 2"));
  if (doc["format"].get<int>() != kDiffFinalFormat)
    return std::unexpected(bad(ErrorId::AppDiffFormat, what, 0,
                               fmt::format("format {}; nck diff compares format {}", doc["format"].dump(), kDiffFinalFormat)));
  const json& t = doc.contains("time_by_cause") ? doc["time_by_cause"] : json();
  if (!t.is_object() || !t.contains("channels") || !t["channels"].is_array())
    return std::unexpected(bad(ErrorId::AppDiffNotFinal, what, 0, "the final state has no \"time_by_cause\" channels"));
  return doc;
}

std::expected<json, Diagnostic> load_final(const std::string& path) {
  std::error_code ec;
  std::ifstream f(path, std::ios::binary);
  if (!std::filesystem::is_regular_file(path, ec) || !f)
    return std::unexpected(bad(ErrorId::AppDiffUnreadable, path, 0, "cannot read this file"));
  std::stringstream buffer;
  buffer << f.rdbuf();
  const std::string text = buffer.str();
  try {
    return check_final(json::parse(text), path);
  } catch (const json::parse_error& e) {
    return std::unexpected(bad(ErrorId::AppDiffNotFinal, path, line_of(text, e.byte),
                               fmt::format("not JSON ({}); give a file nck run --final wrote", e.what())));
  }
}

ojson diff_finals(const json& a, const json& b) {
  const double ta = number_or(a, "time"), tb = number_or(b, "time");
  ojson out{{"time_a_s", round_us(ta)}, {"time_b_s", round_us(tb)}, {"delta_s", round_us(tb - ta)},
            {"end_a", string_or(a, "end")}, {"end_b", string_or(b, "end")}};
  const std::size_t n = std::max(a["time_by_cause"]["channels"].size(), b["time_by_cause"]["channels"].size());
  ojson channels = ojson::array();
  for (std::size_t i = 0; i < n; ++i) {
    const json& ca = channel_of(a, i);
    const json& cb = channel_of(b, i);
    const json none = json::array();
    const auto side = [&](const json& c, const char* key) -> const json& { return c.contains(key) ? c[key] : none; };
    const auto rows = [&](const char* key, const std::function<std::string(const json&)>& k) {
      return compare(times_of(side(ca, key), k), times_of(side(cb, key), k));
    };
    const std::string main_a = main_file(ca), main_b = main_file(cb);
    const ojson blocks = compare_blocks(side(ca, "blocks"), main_a, side(cb, "blocks"), main_b);
    channels.push_back({{"ch", i + 1},
                        {"time_a_s", round_us(number_or(ca, "time_s"))},
                        {"time_b_s", round_us(number_or(cb, "time_s"))},
                        {"causes", rows("causes", [](const json& r) { return string_or(r, "name"); })},
                        {"tools", rows("tools", [](const json& r) { return string_or(r, "tool"); })},
                        {"subroutines", rows("subroutines", file_key)},
                        {"blocks", blocks}});
  }
  out["channels"] = channels;
  return out;
}

namespace {

// The table's first column: a block's NC text fits (N number and a few words).
constexpr std::size_t kKeyWidth = 40;

// At most `width` bytes of `key` (a block's NC text can be long; --json has
// it whole), never cutting a UTF-8 character.
std::string shortened(const std::string& key, std::size_t width) {
  if (key.size() <= width) return key;
  std::size_t end = width - 3;
  while (end > 0 && (static_cast<unsigned char>(key[end]) & 0xC0) == 0x80) --end;
  return key.substr(0, end) + "...";
}

std::string seconds_text(const ojson& v) { return v.is_number() ? fmt::format("{:.3f}", v.get<double>()) : "-"; }

void table(std::string& s, const std::string& title, const ojson& rows, std::size_t max_rows) {
  if (!rows.is_array() || rows.empty()) return;
  s += fmt::format("\n{:<{}} {:>12} {:>12} {:>12}\n", title, kKeyWidth + 2, "A (s)", "B (s)", "B - A (s)");
  for (std::size_t i = 0; i < rows.size() && i < max_rows; ++i) {
    const ojson& r = rows[i];
    s += fmt::format("  {:<{}} {:>12} {:>12} {:>+12.3f}\n", shortened(r["key"].get<std::string>(), kKeyWidth),
                     kKeyWidth, seconds_text(r["a_s"]), seconds_text(r["b_s"]), r["delta_s"].get<double>());
  }
  if (rows.size() > max_rows) s += fmt::format("  ... {} more (--json lists all)\n", rows.size() - max_rows);
}

}  // namespace

std::string diff_table(const ojson& d, std::size_t max_rows) {
  const double ta = d["time_a_s"].get<double>(), tb = d["time_b_s"].get<double>();
  std::string s = fmt::format("cycle time: A {:.3f} s, B {:.3f} s, B - A {:+.3f} s ({})\n", ta, tb, tb - ta,
                              ta > 0 ? fmt::format("{:+.1f} %", 100 * (tb - ta) / ta) : std::string("-"));
  if (d["end_a"] != d["end_b"])
    s += fmt::format("the runs ended differently: A {}, B {}\n", d["end_a"].get<std::string>(), d["end_b"].get<std::string>());
  for (const ojson& ch : d["channels"]) {
    const std::string c = d["channels"].size() > 1 ? fmt::format(" (channel {})", ch["ch"].get<int>()) : "";
    table(s, "by cause" + c, ch["causes"], max_rows);
    table(s, "by tool" + c, ch["tools"], max_rows);
    table(s, "by subroutine file" + c, ch["subroutines"], max_rows);
    table(s, "by block" + c, ch["blocks"], max_rows);
  }
  if (d.contains("path")) {
    const ojson& p = d["path"];
    s += fmt::format("\npath of channel 1: length A {:.3f} mm, B {:.3f} mm; position difference max {:.4f} mm, mean {:.4f} mm\n",
                     p["length_a_mm"].get<double>(), p["length_b_mm"].get<double>(), p["max_mm"].get<double>(),
                     p["mean_mm"].get<double>());
    if (!p["largest"].empty()) s += fmt::format("  {:>8} {:>8} {:>12} {:>12}  {}\n", "line A", "line B", "at s (mm)", "diff (mm)", "A -> B position");
    for (std::size_t i = 0; i < p["largest"].size() && i < max_rows; ++i) {
      const ojson& r = p["largest"][i];
      s += fmt::format("  {:>8} {:>8} {:>12.3f} {:>12.4f}  {} -> {}\n", r["line_a"].get<std::uint32_t>(),
                       r["line_b"].get<std::uint32_t>(), r["s_mm"].get<double>(), r["distance_mm"].get<double>(),
                       r["a"].dump(), r["b"].dump());
    }
  }
  return s;
}

}  // namespace nck::app
