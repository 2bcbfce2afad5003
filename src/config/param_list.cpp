#include "nck/config/param_list.hpp"

#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <set>

#include "registry_internal.hpp"

namespace nck::config {
namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (auto& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// "P-AXIS-00212" or "P-AXIS-00212.0": a value that points at another parameter.
std::optional<std::string> parameter_reference(std::string_view tok) {
  if (tok.size() < 12 || (tok[0] != 'P' && tok[0] != 'p') || tok[1] != '-') return std::nullopt;
  auto dash = tok.find('-', 2);
  if (dash == std::string_view::npos || dash + 6 > tok.size()) return std::nullopt;
  for (std::size_t i = dash + 1; i < dash + 6; ++i)
    if (!std::isdigit(static_cast<unsigned char>(tok[i]))) return std::nullopt;
  return upper(tok.substr(0, dash + 6));
}

struct Pending {
  std::string key;
  std::string ref_id;
};

class LineParser {
 public:
  LineParser(const std::string& file, Diagnostics& diags) : file_(file), diags_(diags) {}

  // Converts the value of `line` for parameter `info`; false on a diagnostic.
  bool convert(const ListLine& line, const ParamInfo& info, ParamValue& out, std::optional<std::string>& ref) {
    auto toks = value_tokens(line.value);
    SourceLoc loc = where(line);
    if (toks.empty()) return bad(loc, fmt::format("'{}' has no value", line.key));
    std::string_view first = toks.front();
    switch (info.type) {
      case ParamType::boolean: {
        auto u = upper(first);
        if (u == "0" || u == "FALSE") out.raw = 0;
        else if (u == "1" || u == "TRUE") out.raw = 1;
        else return bad(loc, fmt::format("'{}' expects 0 or 1, not '{}'", line.key, first));
        return true;
      }
      case ParamType::integer:
      case ParamType::real: {
        if (auto r = parameter_reference(first)) {
          ref = *r;
          return true;
        }
        auto v = parse_number(first);
        if (!v) return bad(loc, fmt::format("'{}' expects a number, not '{}'", line.key, first));
        if (info.type == ParamType::integer && std::fabs(*v - std::round(*v)) > 1e-9)
          return bad(loc, fmt::format("'{}' expects a whole number, not '{}'", line.key, first));
        out.raw = *v;
        return in_range(line, info, out.raw, loc);
      }
      case ParamType::string:
      case ParamType::path:
        if (first.size() > static_cast<std::size_t>(info.max))
          return out_of_range(loc, fmt::format("'{}' is longer than {} characters", line.key, info.max));
        out.text = std::string(first);
        return true;
      case ParamType::choice:
        return choice(line, info, first, out, loc);
      case ParamType::sync:
      case ParamType::achstyp:
      case ParamType::decoder_fct:
        return symbols(line, info, toks, out, loc);
    }
    return false;
  }

 private:
  SourceLoc where(const ListLine& l) const { return SourceLoc{file_, l.line, 0}; }
  bool bad(SourceLoc loc, std::string msg) {
    diags_.add(ErrorId::ConfigBadValue, std::move(loc), std::move(msg));
    return false;
  }
  bool out_of_range(SourceLoc loc, std::string msg) {
    diags_.add(ErrorId::ConfigOutOfRange, std::move(loc), std::move(msg));
    return false;
  }
  bool in_range(const ListLine& line, const ParamInfo& info, double v, SourceLoc loc) {
    if (v >= info.min && v <= info.max) return true;
    return out_of_range(loc, fmt::format("'{}' = {} is outside {} … {}", line.key, v, info.min, info.max));
  }
  bool choice(const ListLine& line, const ParamInfo& info, std::string_view first, ParamValue& out,
              SourceLoc loc) {
    auto u = upper(first);
    for (auto c : value_tokens(info.choices))
      if (c == u) {
        out.text = u;
        return true;
      }
    return bad(loc, fmt::format("'{}' expects one of {}, not '{}'", line.key, info.choices, first));
  }
  // OR-s symbols and numbers; the first other token starts a free remark.
  bool symbols(const ListLine& line, const ParamInfo& info, const std::vector<std::string_view>& toks,
               ParamValue& out, SourceLoc loc) {
    std::uint64_t bits = 0;
    std::size_t used = 0;
    for (auto t : toks) {
      if (auto s = symbol_value(info.type, t)) bits |= *s;
      else if (auto n = parse_number(t); n && *n >= 0 && *n <= 4294967295.0 && *n == std::floor(*n))
        bits |= static_cast<std::uint64_t>(*n);
      else break;
      ++used;
    }
    if (used == 0) return bad(loc, fmt::format("'{}' expects symbolic constants or a hex number, not '{}'",
                                               line.key, toks.front()));
    out.raw = static_cast<double>(bits);
    if (info.type == ParamType::achstyp && bits != 1 && bits != 2 && bits != 4)
      return out_of_range(loc, fmt::format("'{}' = 0x{:x} is not 0x1, 0x2 or 0x4", line.key, bits));
    return true;
  }

  const std::string& file_;
  Diagnostics& diags_;
};

// Resolves the key of `line` to a registry entry (directly or via an alias);
// nullptr when it is neither.
const ParamInfo* resolve_key(const ListLine& line, ListKind kind, const std::string& file,
                             detail::KeyParts& parts, std::string& canonical, Diagnostics& diags) {
  canonical = line.key;
  parts = detail::split_key(canonical);
  const ParamInfo* info = parts.ok ? find_parameter(kind, parts.pattern) : nullptr;
  if (info) return info;
  auto alias = rewrite_alias(kind, canonical);
  if (!alias) return nullptr;
  if (alias->warn)
    diags.add(ErrorId::ConfigKeyAlias, SourceLoc{file, line.line, 0},
              fmt::format("'{}' is read as '{}'; write it that way", line.key, alias->key));
  canonical = alias->key;
  parts = detail::split_key(canonical);
  return find_parameter(kind, parts.pattern);
}

// Unknown keys past the file's diagnostic cap: counted, not listed.
struct UnlistedKeys {
  std::size_t count = 0;
  std::size_t misspelt = 0;
  SourceLoc first_misspelt;     // where the first misspelt one stands
  std::string first_misspelt_text;
};

std::string misspelling_text(std::string_view key, ListKind kind, const std::string& meant) {
  const ParamInfo* info = find_parameter(kind, detail::split_key(meant).pattern);
  return fmt::format("'{}' misspells '{}' ({})", key, meant, info ? info->id : "nck");
}

// An unknown key. A misspelling is error 910031: the parameter it means
// would keep its default unnoticed. Any other key is warning 910002 and
// has no effect (lists written for TF5200 carry many keys nck does not
// model), error 910032 under KeyPolicy::strict. `quiet`: the file's
// diagnostics are at their cap, so the key is only counted and not searched
// for its nearest known key (the costly part: 300,000 unknown keys took
// 20 s); the misspelling search, bounded at distance 2, still runs.
void report_unknown_key(const ListLine& line, ListKind kind, const std::string& file,
                        const detail::KeyParts& parts, KeyPolicy keys, bool quiet, UnlistedKeys& unlisted,
                        Diagnostics& diags) {
  const SourceLoc loc{file, line.line, 0};
  const std::optional<std::string> meant = misspelt_key(kind, line.key);
  if (quiet) {
    unlisted.count += 1;
    if (meant && unlisted.misspelt++ == 0) {
      unlisted.first_misspelt = loc;
      unlisted.first_misspelt_text = misspelling_text(line.key, kind, *meant);
    }
    return;
  }
  if (meant) {
    diags.add(ErrorId::ConfigKeyTypo, loc,
              fmt::format("unknown key in the {} list: {}, which keeps its default; write '{}'", list_name(kind),
                          misspelling_text(line.key, kind, *meant), *meant));
    return;
  }
  const std::string nearest = detail::join_key(nearest_key(kind, parts.pattern), parts.index);
  diags.add(keys == KeyPolicy::strict ? ErrorId::ConfigUnknownKeyStrict : ErrorId::ConfigUnknownKey, loc,
            fmt::format("unknown key '{}' in the {} list, no effect; nearest known key: '{}'", line.key,
                        list_name(kind), nearest));
}

// One diagnostic for the keys past the cap: an error when one of them is
// misspelt (at its line), else as report_unknown_key would have reported them.
void report_unlisted_keys(const UnlistedKeys& unlisted, ListKind kind, const std::string& file, KeyPolicy keys,
                          Diagnostics& diags) {
  if (unlisted.count == 0) return;
  const std::string text =
      fmt::format("{} more unknown key(s) in the {} list are not listed (the first {} diagnostics of the file are)",
                  unlisted.count, list_name(kind), kMaxKeyDiagnosticsPerList);
  if (unlisted.misspelt > 0)
    diags.add(ErrorId::ConfigKeyTypo, unlisted.first_misspelt,
              fmt::format("{}; {} of them misspell a known key, the first here: {}", text, unlisted.misspelt,
                          unlisted.first_misspelt_text));
  else
    diags.add(keys == KeyPolicy::strict ? ErrorId::ConfigUnknownKeyStrict : ErrorId::ConfigUnknownKey,
              SourceLoc{file, 0, 0}, text);
}

bool index_ok(const ListLine& line, const ParamInfo& info, const detail::KeyParts& parts,
              const std::string& file, Diagnostics& diags) {
  for (std::size_t n = 0; n < parts.index_count; ++n) {
    if (parts.index[n] < info.index_count[n]) continue;
    diags.add(ErrorId::ConfigOutOfRange, SourceLoc{file, line.line, 0},
              fmt::format("index {} of '{}' is too large (at most {})", parts.index[n], line.key,
                          info.index_count[n] - 1));
    return false;
  }
  return true;
}

}  // namespace

ParamList ParamList::parse(const ListText& text, ListKind kind, Diagnostics& diags, KeyPolicy keys) {
  ParamList list(kind, text.file);
  LineParser parser(text.file, diags);
  std::vector<Pending> pending;
  const std::size_t first_diagnostic = diags.items().size();
  UnlistedKeys unlisted;
  for (const auto& line : text.lines) {
    detail::KeyParts parts;
    std::string canonical;
    const bool quiet = diags.items().size() - first_diagnostic >= kMaxKeyDiagnosticsPerList;
    const ParamInfo* info = resolve_key(line, kind, text.file, parts, canonical, diags);
    if (!info) report_unknown_key(line, kind, text.file, parts, keys, quiet, unlisted, diags);
    if (!info || !index_ok(line, *info, parts, text.file, diags)) continue;
    ParamValue v{info, canonical, parts.index, 0, {}, SourceLoc{text.file, line.line, 0}};
    std::optional<std::string> ref;
    if (!parser.convert(line, *info, v, ref)) {
      list.rejected_.insert(canonical);
      continue;
    }
    if (auto it = list.values_.find(canonical); it != list.values_.end())
      diags.add(ErrorId::ConfigDuplicateKey, v.loc,
                fmt::format("'{}' was already set in line {}; this line wins", canonical, it->second.loc.line));
    std::erase_if(pending, [&](const Pending& p) { return p.key == canonical; });
    if (ref) pending.push_back({canonical, *ref});
    list.values_[canonical] = std::move(v);
  }
  report_unlisted_keys(unlisted, kind, text.file, keys, diags);
  // Values written as another parameter's ID take that parameter's value.
  for (int pass = 0; pass < 4; ++pass)
    for (const auto& p : pending) {
      auto& v = list.values_[p.key];
      const ParamInfo* target = find_parameter_by_id(kind, p.ref_id);
      if (!target) continue;
      const ParamValue* src = list.find(detail::join_key(target->key, v.index));
      v.raw = src ? src->raw : target->def;
    }
  for (const auto& p : pending) {
    if (find_parameter_by_id(kind, p.ref_id)) continue;
    diags.add(ErrorId::ConfigBadValue, list.values_[p.key].loc,
              fmt::format("'{}' refers to unknown parameter {}", p.key, p.ref_id));
    list.values_.erase(p.key);
  }
  return list;
}

void ParamList::take_defaults_from(const ParamList& defaults) {
  for (const auto& [k, v] : defaults.values_) values_.try_emplace(k, v);
}

const ParamValue* ParamList::find(std::string_view key) const {
  auto it = values_.find(key);
  return it == values_.end() ? nullptr : &it->second;
}

double ParamList::num(std::string_view key, double fallback) const {
  const ParamValue* v = find(key);
  return v ? v->value() : fallback;
}

std::uint32_t ParamList::u32(std::string_view key, std::uint32_t fallback) const {
  const ParamValue* v = find(key);
  if (!v) return fallback;
  double d = v->value();
  if (d <= 0) return 0;
  return d >= 4294967295.0 ? 0xffffffffu : static_cast<std::uint32_t>(std::llround(d));
}

std::string ParamList::text(std::string_view key, std::string fallback) const {
  const ParamValue* v = find(key);
  return v ? v->text : fallback;
}

SourceLoc ParamList::loc(std::string_view key) const {
  const ParamValue* v = find(key);
  return v ? v->loc : SourceLoc{file_, 0, 0};
}

std::vector<std::uint32_t> ParamList::indices(std::string_view prefix, std::size_t position) const {
  std::set<std::uint32_t> seen;
  for (auto it = values_.lower_bound(prefix); it != values_.end() && it->first.starts_with(prefix); ++it)
    seen.insert(it->second.index[position < 3 ? position : 0]);
  return {seen.begin(), seen.end()};
}

SourceLoc ParamList::loc_prefix(std::string_view prefix) const {
  SourceLoc best{file_, 0, 0};
  for (auto it = values_.lower_bound(prefix); it != values_.end() && it->first.starts_with(prefix); ++it)
    if (best.line == 0 || it->second.loc.line < best.line) best = it->second.loc;
  return best;
}

bool ParamList::any_with_prefix(std::string_view prefix) const {
  auto it = values_.lower_bound(prefix);
  return it != values_.end() && it->first.starts_with(prefix);
}

}  // namespace nck::config
