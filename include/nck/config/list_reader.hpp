#pragma once
// Reads the ISG list syntax into key/value lines, without knowing any key:
//   key  value  [free remark | # comment | ( remark]
// '#' lines are comments, a line "Ende" ends the list. Keys are returned in
// lower case (ISG lists mix "Wz[5]" and "wz[5]"); values keep their case.
// Bad lines (binary data, > 4096 characters, not a key) become diagnostics.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nck/core/diagnostic.hpp"

namespace nck::config {

inline constexpr std::size_t kMaxListLineLength = 4096;
inline constexpr std::size_t kMaxListFileBytes = 64u * 1024u * 1024u;
inline constexpr std::size_t kMaxDiagnosticsPerList = 50;  // of the line syntax
// Of the keys and values (ParamList::parse): further unknown keys are counted only.
inline constexpr std::size_t kMaxKeyDiagnosticsPerList = 200;

struct ListLine {
  std::string key;     // lower case, e.g. "spindel[0].m3_synch"
  std::string value;   // text after the key, remark after '#' / '(' removed, trimmed
  std::uint32_t line = 0;
};

struct ListText {
  std::string file;  // name used in diagnostics
  std::vector<ListLine> lines;
};

// Splits `text` into key/value lines; `file` is used for diagnostics only.
ListText read_list_text(std::string_view text, std::string file, Diagnostics& diags);

// Reads a file; nullopt (and 910001 naming `display_name`) when it cannot be read.
std::optional<ListText> read_list_file(const std::filesystem::path& path,
                                       const std::string& display_name, Diagnostics& diags,
                                       SourceLoc referenced_from = {});

// A number as ISG lists write it: decimal, 0x hex, negative, float with exponent.
std::optional<double> parse_number(std::string_view token);

// The value's tokens, split at blanks, tabs and '|' ("PLC_INFO|MVS_SVS" -> 2 tokens).
std::vector<std::string_view> value_tokens(std::string_view value);

}  // namespace nck::config
