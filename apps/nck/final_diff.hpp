#pragma once
// `nck diff`'s comparison of two final states (--final, format 2): the
// cycle time, and time by cause per cause, per tool, per subroutine file
// and per block (NC line), B against A. Pure data in, data out; the
// command (diff_command.cpp) reads the files and prints.
#include <expected>
#include <string>

#include <nlohmann/json.hpp>

#include "nck/core/diagnostic.hpp"

namespace nck::app {

// The final-state format nck diff compares (docs/outputs.md).
inline constexpr int kDiffFinalFormat = 2;

// A --final file, checked: readable, JSON, a final state of format 2 with
// time_by_cause. Else a diagnostic with its ID and the file as location.
std::expected<nlohmann::json, Diagnostic> load_final(const std::string& path);
// The same check of a document already parsed (`what`: where it came from).
std::expected<nlohmann::json, Diagnostic> check_final(nlohmann::json doc, const std::string& what);

// {"time_a_s", "time_b_s", "delta_s", "channels": [{"ch", "causes", "tools",
// "subroutines", "blocks"}]}: rows {key, a_s, b_s, delta_s}, the largest
// change first; a row one side lacks has null there. Blocks are matched by
// identity (block_pairs.hpp: file name, local subroutine, NC text, pass;
// then by N number), whatever line they stand on; only the lines each
// --final lists (its 2,000 most time-losing) can be matched.
nlohmann::ordered_json diff_finals(const nlohmann::json& a, const nlohmann::json& b);

// The readable table of diff_finals (and of "path", when present): at most
// `rows` rows per table.
std::string diff_table(const nlohmann::ordered_json& diff, std::size_t rows = 10);

}  // namespace nck::app
