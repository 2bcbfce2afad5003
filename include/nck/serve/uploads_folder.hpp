#pragma once
// The folder nck serve stores uploaded programs in (docs/api.md, "Files").
// By default a new private one: made by mkdtemp (an unpredictable name,
// mode 0700, never a folder that existed before) and removed when the
// server ends. A folder --uploads names is kept, and refused when an
// upload could replace what the machine or a program reads: a folder that
// is or contains the machine folder, a cycle path or a programs folder, or
// that lies on a pseudo file system (/proc, /sys, /dev).
#include <expected>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "nck/core/diagnostic.hpp"

namespace nck::app::serve {

class UploadsFolder {
 public:
  // A new private folder under the system's temporary folder.
  static std::expected<UploadsFolder, Diagnostic> create_private();
  // The folder `dir` (made, mode 0700, when missing); `guarded`: the
  // folders it may neither be nor contain.
  static std::expected<UploadsFolder, Diagnostic> named(const std::filesystem::path& dir,
                                                        const std::vector<std::filesystem::path>& guarded);
  UploadsFolder(UploadsFolder&& other) noexcept;
  UploadsFolder& operator=(UploadsFolder&&) = delete;
  UploadsFolder(const UploadsFolder&) = delete;
  ~UploadsFolder();  // removes a private folder with what it holds

  // Canonical.
  const std::filesystem::path& path() const { return path_; }

 private:
  UploadsFolder(std::filesystem::path path, bool remove_at_end) : path_(std::move(path)), remove_at_end_(remove_at_end) {}
  std::filesystem::path path_;
  bool remove_at_end_;
};

// Writes `text` as file `name` of `folder` and never through a link: into
// a new temporary file of the folder (O_EXCL, O_NOFOLLOW, mode 0600),
// renamed over `name` (a link of that name is replaced, its target never
// written). A reader sees the old file or the new one, never half of one.
// false when the folder cannot be written.
bool write_replacing(const std::filesystem::path& folder, std::string_view name, std::string_view text);

}  // namespace nck::app::serve
