#pragma once
// Writing an edited list file back (issue 48 item 8): only the values of the
// edited keys change; every other line, its comment and the columns stay as
// the operator wrote them. A key the file does not name yet is added before
// its "Ende" line. The file on disk is replaced only whole: the new text
// goes to a temporary file beside it that is renamed over it, after the old
// file was copied to FILE.bak.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace nck::app::serve {

// A file's contents as loaded: what a save compares the disk against.
struct ListFingerprint {
  std::uint64_t hash = 0;  // FNV-1a of the bytes
  std::uintmax_t size = 0;
  bool operator==(const ListFingerprint&) const = default;
};
ListFingerprint fingerprint_of(std::string_view bytes) noexcept;
// The file's fingerprint, or nullopt when it cannot be read.
std::optional<ListFingerprint> fingerprint_file(const std::filesystem::path& file);

// `text` with the value of every key in `values` (lower-case keys) replaced,
// the remark after it kept in its column where the value fits; the keys no
// line names inserted before "Ende" (or at the end).
std::string rewrite_list(std::string_view text, const std::map<std::string, std::string>& values);

// Writes `text` to `file` through FILE.tmp and a rename, the old file kept
// as FILE.bak; the reason when it could not (then `file` is as it was).
std::optional<std::string> replace_file_with_backup(const std::filesystem::path& file, std::string_view text);

}  // namespace nck::app::serve
