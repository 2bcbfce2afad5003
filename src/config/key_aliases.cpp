// The other spellings of list keys that nck accepts (the seeds' misspellings,
// the short axis forms), and the search that takes an unknown key for a
// misspelling of a known one (910031, docs/decisions.md "Reading and
// checking the lists").
#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <vector>

#include "nck/core/edit_distance.hpp"
#include "registry_internal.hpp"

namespace nck::config {
namespace {

// One seed spelling: `from` (as a seed writes it) stands for `to` (the
// reference key's part), at the key's start (`prefix`) or anywhere in it;
// `within`: only in keys that start so. "[]" in `to` is an index the seed
// form leaves out, which is 0.
struct SeedSpelling {
  ListKind list;
  std::string_view from;
  std::string_view to;
  bool prefix;
  std::string_view within = {};
};

// In the order they apply: log_achs_no is rewritten after spindle -> spindel.
constexpr SeedSpelling kSeedSpellings[] = {
    {ListKind::channel, "spindle[", "spindel[", true},
    {ListKind::channel, ".log_achs_no", ".log_achs_nr", false, "spindel["},
    {ListKind::channel, "koppelgruppe[", "synchro_data.koppel_gruppe[", true},
    {ListKind::channel, "koppel_gruppe[", "synchro_data.koppel_gruppe[", true},
    {ListKind::axis, ".mulit_gain_n", ".multi_gain_n", false},
    {ListKind::axis, "beschl_kennlinie.", "getriebe[].beschl_kennlinie.", true},
    {ListKind::zero, ".versatz", ".versch", false, "np_grp["},
    {ListKind::startup, "wrkz_data[", "werkz_data[", true},
};

// The seeds write axis keys of kenngr without it (achs_typ, antr_typ ...).
constexpr std::string_view kShortFormPrefix = "kenngr.";

std::string with_zero_indices(std::string_view part) {
  std::string out(part);
  for (auto at = out.find("[]"); at != std::string::npos; at = out.find("[]", at)) out.insert(at + 1, "0");
  return out;
}

// A seed spelling in a concrete key -> the reference spelling; false if it has none.
bool rewrite(const SeedSpelling& s, std::string& key) {
  if (!s.within.empty() && !key.starts_with(s.within)) return false;
  if (s.prefix) {
    if (!key.starts_with(s.from)) return false;
    key = with_zero_indices(s.to) + key.substr(s.from.size());
    return true;
  }
  const auto at = key.find(s.from);
  if (at == std::string::npos) return false;
  key.replace(at, s.from.size(), with_zero_indices(s.to));
  return true;
}

// The other way, on patterns: the seed spelling of a reference pattern, if it has one.
std::optional<std::string> seed_form(const SeedSpelling& s, std::string_view pattern) {
  if (!s.within.empty() && !pattern.starts_with(s.within)) return std::nullopt;
  if (s.prefix) {
    if (!pattern.starts_with(s.to)) return std::nullopt;
    return std::string(s.from) + std::string(pattern.substr(s.to.size()));
  }
  const auto at = pattern.find(s.to);
  if (at == std::string_view::npos) return std::nullopt;
  return std::string(pattern.substr(0, at)) + std::string(s.from) + std::string(pattern.substr(at + s.to.size()));
}

// Every spelling of a key that resolves: the key itself, its seed forms
// (each combination: "spindle[].log_achs_no"), its short form.
struct Spelling {
  std::string pattern;
  const ParamInfo* info = nullptr;
  std::size_t indices = 0;  // "[]" in pattern
  std::string plain;        // pattern without_numbers
};

std::size_t index_count(std::string_view pattern) {
  std::size_t n = 0;
  for (auto at = pattern.find("[]"); at != std::string_view::npos; at = pattern.find("[]", at + 2)) ++n;
  return n;
}

// "m19_synch" -> "m_synch", "swe_pos_2" -> "swe_pos": what is left of a key
// without its numbers (and the '_' that introduces one).
std::string without_numbers(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const bool digit = std::isdigit(static_cast<unsigned char>(s[i])) != 0;
    const bool number_follows = s[i] == '_' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1]));
    if (!digit && !number_follows) out.push_back(s[i]);
  }
  return out;
}

Spelling spelling(std::string pattern, const ParamInfo* info) {
  Spelling s;
  s.pattern = std::move(pattern);
  s.info = info;
  s.indices = index_count(s.pattern);
  s.plain = without_numbers(s.pattern);
  return s;
}

void add_seed_forms(std::vector<Spelling>& out) {
  // Backwards, so that a form one rule makes is there for the rules before it.
  for (auto s = std::rbegin(kSeedSpellings); s != std::rend(kSeedSpellings); ++s)
    for (std::size_t i = 0, end = out.size(); i < end; ++i)
      if (out[i].info->list == s->list)
        if (auto form = seed_form(*s, out[i].pattern))
          out.push_back(spelling(std::move(*form), out[i].info));
}

const std::vector<Spelling>& spellings() {
  static const std::vector<Spelling> all = [] {
    std::vector<Spelling> out;
    for (const ParamInfo& p : all_parameters()) out.push_back(spelling(std::string(p.key), &p));
    const std::size_t known = out.size();
    add_seed_forms(out);
    for (std::size_t i = 0; i < known; ++i)
      if (out[i].info->list == ListKind::axis && out[i].pattern.starts_with(kShortFormPrefix))
        out.push_back(spelling(out[i].pattern.substr(kShortFormPrefix.size()), out[i].info));
    return out;
  }();
  return all;
}

// A name of one or two letters (kv, id, kp): one letter more or less makes another word.
bool short_name(std::string_view pattern) {
  const auto dot = pattern.rfind('.');
  std::string_view last = dot == std::string_view::npos ? pattern : pattern.substr(dot + 1);
  std::size_t letters = 0;
  for (char c : last) letters += c != '[' && c != ']';
  return letters < 3;
}

constexpr std::size_t kMaxTypoDistance = 2;

// The cheap conditions first: the same number of indices, a length within
// reach, no short name.
bool may_misspell(const detail::KeyParts& key, const Spelling& s) {
  const std::size_t a = key.pattern.size(), b = s.pattern.size();
  return s.indices == key.index_count && (a > b ? a - b : b - a) <= kMaxTypoDistance && !short_name(s.pattern);
}

// Only the numbers differ (m6_synch beside m3_synch, swe_pos_2 beside
// swe_pos): a numbered parameter of its own that nck does not model.
bool numbered_sibling(ListKind list, const detail::KeyParts& key, std::string_view plain) {
  return std::any_of(spellings().begin(), spellings().end(), [&](const Spelling& s) {
    return s.info->list == list && s.indices == key.index_count && s.plain == plain;
  });
}

}  // namespace

std::optional<KeyRewrite> rewrite_alias(ListKind list, std::string_view key) {
  std::string k(key);
  bool changed = false;
  for (const SeedSpelling& s : kSeedSpellings)
    if (s.list == list) changed |= rewrite(s, k);
  if (changed) {
    if (find_parameter(list, detail::split_key(k).pattern)) return KeyRewrite{k, true};
    return std::nullopt;
  }
  if (list == ListKind::axis && k.find('.') == std::string::npos) {
    std::string full = std::string(kShortFormPrefix) + k;
    if (find_parameter(list, detail::split_key(full).pattern)) return KeyRewrite{full, false};
  }
  return std::nullopt;
}

std::vector<std::string> alias_patterns(const ParamInfo& p) {
  std::vector<std::string> out;
  for (const Spelling& s : spellings())
    if (s.info == &p && s.pattern != p.key) out.push_back(s.pattern);
  return out;
}

std::string alias_summary() {
  std::string out;
  for (const SeedSpelling& s : kSeedSpellings) {
    if (!out.empty()) out += ", ";
    const std::string to = display_key(s.to);
    if (s.prefix) out += fmt::format("`{}…` for `{}…`", display_key(s.from), to);
    else out += fmt::format("`…{}` for `…{}`", s.from, to);
    if (!s.within.empty()) out += fmt::format(" (in `{}…`)", display_key(s.within));
  }
  return out;
}

std::optional<std::string> misspelt_key(ListKind list, std::string_view key) {
  const detail::KeyParts parts = detail::split_key(key);
  if (!parts.ok) return std::nullopt;
  if (numbered_sibling(list, parts, without_numbers(parts.pattern))) return std::nullopt;
  const Spelling* best = nullptr;
  std::size_t best_distance = kMaxTypoDistance + 1;
  for (const Spelling& s : spellings()) {
    if (s.info->list != list || !may_misspell(parts, s)) continue;
    const std::size_t d = edit_distance(parts.pattern, s.pattern, best_distance);
    if (d >= best_distance) continue;
    best = &s;
    best_distance = d;
  }
  if (!best) return std::nullopt;
  return detail::join_key(best->info->key, parts.index);
}

}  // namespace nck::config
