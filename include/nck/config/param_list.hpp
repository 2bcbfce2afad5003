#pragma once
// One list file checked against the parameter registry: every known key with
// its typed value (list units) and source line. Unknown keys, wrong types and
// values out of range become diagnostics here; the loader builds the typed
// machine model from what is left.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "nck/config/list_reader.hpp"
#include "nck/config/parameter_registry.hpp"
#include "nck/core/diagnostic.hpp"

namespace nck::config {

struct ParamValue {
  const ParamInfo* info = nullptr;
  std::string key;                         // canonical concrete key
  std::array<std::uint32_t, 3> index{};
  double raw = 0;                          // numbers, booleans, symbol bits (list units)
  std::string text;                        // strings, paths, choices
  SourceLoc loc;
  double value() const { return raw * info->scale; }  // internal units
};

class ParamList {
 public:
  ParamList() = default;
  ParamList(ListKind kind, std::string file) : kind_(kind), file_(std::move(file)) {}

  // Checks every line of `text` against the registry for `kind`; `keys`:
  // how a key that is neither known nor misspelt is reported.
  static ParamList parse(const ListText& text, ListKind kind, Diagnostics& diags,
                         KeyPolicy keys = KeyPolicy::lenient);

  // Entries of `defaults` that this list does not set are taken over.
  void take_defaults_from(const ParamList& defaults);

  const ParamValue* find(std::string_view key) const;
  bool has(std::string_view key) const { return find(key) != nullptr; }
  // Internal units; `fallback` when the key is not given.
  double num(std::string_view key, double fallback) const;
  std::uint32_t u32(std::string_view key, std::uint32_t fallback) const;
  bool flag(std::string_view key, bool fallback) const { return num(key, fallback ? 1 : 0) != 0; }
  std::string text(std::string_view key, std::string fallback) const;
  // Where a key was given; the file with line 0 when it was not.
  SourceLoc loc(std::string_view key) const;
  // Distinct values of index `position` of keys starting with `prefix`
  // ("spindel[", 0 -> {0, 1}; "gruppe[0].achse[", 1 -> {0, 1, 2}).
  std::vector<std::uint32_t> indices(std::string_view prefix, std::size_t position = 0) const;
  // Earliest line of a key starting with `prefix` (file, line 0 when none).
  SourceLoc loc_prefix(std::string_view prefix) const;
  // Given, but its value was refused (a diagnostic says why at its line).
  bool rejected(std::string_view key) const { return rejected_.contains(key); }
  // True when any key starts with `prefix`.
  bool any_with_prefix(std::string_view prefix) const;

  const std::map<std::string, ParamValue, std::less<>>& values() const { return values_; }
  const std::string& file() const { return file_; }
  ListKind kind() const { return kind_; }

 private:
  ListKind kind_ = ListKind::startup;
  std::string file_;
  std::map<std::string, ParamValue, std::less<>> values_;
  std::set<std::string, std::less<>> rejected_;
};

}  // namespace nck::config
