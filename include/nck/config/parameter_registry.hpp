#pragma once
// The parameter registry: one table of every key nck accepts in a list file,
// with its TF5200 ID, type, units, range, default and meaning. The loader
// validates values against it and docs/parameters.md is rendered from it.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace nck::config {

enum class ListKind : std::uint8_t { startup, channel, axis, tool, zero, clamp, sim };

enum class ParamType : std::uint8_t {
  boolean,   // 0/1, TRUE/FALSE
  integer,   // decimal, 0x hex or negative; must be integral
  real,      // any number, exponent allowed
  string,    // one identifier token (names)
  path,      // a file path, relative to the machine folder
  choice,    // one of ParamInfo::choices
  sync,      // synchronisation symbols / hex, OR-ed (P-CHAN-00041 set)
  achstyp,   // ACHSTYP_* symbol or number
  decoder_fct,  // FCT_* symbols, OR-ed; '-' = none
};

struct ParamInfo {
  std::string_view key;      // pattern with empty brackets: "getriebe[].dynamik.vb_max"
  std::string_view id;       // "P-AXIS-00212", or "nck" for nck's own keys
  ListKind list;
  ParamType type;
  double min;                // range in list units (strings: unused)
  double max;
  double def;                // default in list units (numeric types)
  double scale;              // internal value = list value * scale
  std::string_view list_unit;
  std::string_view internal_unit;
  std::string_view meaning;  // one line, own words
  std::array<std::uint16_t, 3> index_count{};  // allowed count per [] in key order
  std::string_view choices{};       // space separated (choice type)
  std::string_view text_default{};  // default shown for non-numeric types
};

// Every accepted key, grouped by list.
std::span<const ParamInfo> all_parameters();
// Lookup by normalised pattern (lower case, indices removed: "spindel[].bezeichnung").
const ParamInfo* find_parameter(ListKind list, std::string_view pattern);
const ParamInfo* find_parameter_by_id(ListKind list, std::string_view id);
// The known key of `list` nearest to `pattern` by edit distance.
std::string_view nearest_key(ListKind list, std::string_view pattern);
std::string_view list_name(ListKind list);

// A seed misspelling or short form, rewritten to its reference key.
struct KeyRewrite {
  std::string key;        // concrete canonical key, e.g. "spindel[0].log_achs_nr"
  bool warn = false;      // true for misspellings (910005), false for accepted short forms
};
// nullopt when `key` (lower case, concrete) is no known alias of `list`.
std::optional<KeyRewrite> rewrite_alias(ListKind list, std::string_view key);
// The other spellings of p's key that rewrite_alias accepts, as patterns
// ("spindle[].log_achs_no", "spindel[].log_achs_no" ... for spindel[].log_achs_nr).
std::vector<std::string> alias_patterns(const ParamInfo& p);
// The accepted seed spellings in one markdown line ("`spindle[…` for `spindel[…`, ...").
std::string alias_summary();

// How a key that is neither known nor an alias is reported (docs/cli.md, --strict).
enum class KeyPolicy : std::uint8_t {
  lenient,  // warning 910002, no effect: lists written for TF5200 carry keys nck does not model
  strict,   // error 910032
};
// The known key an unknown `key` (lower case, concrete) misspells, as a
// concrete key with key's indices: within edit distance 2 of a known key or
// of one of its alias_patterns, with the same number of indices, not a
// numbered sibling (only digits differ: m3_synch / m6_synch, swe_pos /
// swe_pos_2) and not a short name (under 3 letters: kv, id). nullopt otherwise.
std::optional<std::string> misspelt_key(ListKind list, std::string_view key);

// Symbol value for the symbol types (sync, achstyp, decoder_fct); nullopt if unknown.
std::optional<std::uint32_t> symbol_value(ParamType type, std::string_view name);

// docs/parameters.md: one markdown table per list.
std::string parameters_markdown();
// A key pattern as docs/parameters.md shows it: "spindel[].range_table[]" -> "spindel[i].range_table[j]".
std::string display_key(std::string_view pattern);

}  // namespace nck::config
