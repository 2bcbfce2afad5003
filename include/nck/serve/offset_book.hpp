#pragma once
// The zero offsets (G54..G59), clamp offsets and tool table of the served
// machine as the HMI edits them (issue 48 item 8). An edit is checked by
// the list loader's rules (the registry's range of the key, an offset,
// group, axis or tool the lists define, vb_min <= vb_max), changes the
// server's copy of the machine and is remembered as the list value of its
// key; save() writes the remembered values into the list files, each only
// when it is still the file that was loaded.
#include <cstdint>
#include <expected>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/serve/list_rewrite.hpp"

namespace nck::app::serve {

// A tool edit: the fields given (mm, rpm, deg/s^2); the others stay.
struct ToolEdit {
  std::optional<double> length_mm, radius_mm, vb_min_rpm, vb_max_rpm, a_max_deg_s2;
};

// "G54".."G59" -> zero-offset group 1..6; nullopt for anything else.
std::optional<std::size_t> zero_group_of(std::string_view offset);
// The channel axis called `axis` (case as the channel list writes it), or nullopt.
std::optional<std::size_t> channel_axis_of(const config::ChannelConfig& c, std::string_view axis);

class OffsetBook {
 public:
  // Fingerprints of the machine's zero, clamp and tool lists as loaded.
  explicit OffsetBook(const config::Machine& m);

  // Every channel's tables (docs/api.md, GET /api/v1/offsets).
  nlohmann::ordered_json tables_json(const config::Machine& m) const;

  std::optional<Diagnostic> set_zero(config::Machine& m, std::size_t ch, std::string_view offset,
                                     std::string_view axis, double value_mm);
  std::optional<Diagnostic> set_clamp(config::Machine& m, std::size_t ch, std::size_t group, std::string_view axis,
                                      double value_mm);
  std::optional<Diagnostic> set_tool(config::Machine& m, std::size_t ch, std::size_t tool, const ToolEdit& e);

  // Writes every edited list file back (the old one kept as FILE.bak);
  // the files written, or the refusal (then no file was written: every file
  // is checked before the first is replaced).
  std::expected<std::vector<std::string>, Diagnostic> save();
  // The lists were loaded again: new fingerprints, no edits.
  void reloaded(const config::Machine& m);
  bool unsaved() const { return !edits_.empty(); }

 private:
  void fingerprint(const std::filesystem::path& file);
  void remember(const std::filesystem::path& file, std::string key, std::string list_value);

  std::filesystem::path folder_;  // the machine folder: only files inside it are written
  std::map<std::filesystem::path, std::optional<ListFingerprint>> loaded_;      // per list file
  std::map<std::filesystem::path, std::map<std::string, std::string>> edits_;  // per file: key -> list value
};

}  // namespace nck::app::serve
