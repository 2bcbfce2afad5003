#pragma once
// The files nck serve may read: programs inside the --programs folders, the
// machine folder and the folder uploads go to. A name is resolved inside
// one of them with symbolic links followed; "..", a link that leads out, a
// file that is no regular file or larger than the bound is refused with an
// ID before any run starts. The decoder holds every file a program opens
// (L subroutines, cycles) to the same folders (DecoderConfig::allowed_roots).
#include <cstdint>
#include <expected>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "nck/core/diagnostic.hpp"

namespace nck::app::serve {

class ProgramFolders {
 public:
  // roots: --programs folders first, then the machine folder; uploads: the
  // folder of the server's own (UploadsFolder: it exists).
  ProgramFolders(std::vector<std::filesystem::path> roots, std::filesystem::path uploads, std::uintmax_t max_bytes);

  // The program `name` names (relative to a folder, or absolute inside one).
  std::expected<std::filesystem::path, Diagnostic> resolve(std::string_view name) const;
  // Programs one may load: names relative to their folder (first folder
  // wins), at most 1,000; lists, scenarios and notes (.lis .plc .md ...) left out.
  std::vector<std::string> list() const;
  // Stores an uploaded program under `name` (letters, digits, . _ -) in the
  // uploads folder (write_replacing: never through a link); its name for resolve().
  std::expected<std::string, Diagnostic> save_upload(std::string_view name, std::string_view text) const;
  // The uploads folder holds a file `name` (an upload would replace it).
  bool upload_exists(std::string_view name) const;
  // Every folder, canonical: what the decoder may open.
  const std::vector<std::filesystem::path>& roots() const { return roots_; }
  std::uintmax_t max_bytes() const { return max_bytes_; }

 private:
  std::vector<std::filesystem::path> roots_;
  std::filesystem::path uploads_;
  std::uintmax_t max_bytes_;
};

}  // namespace nck::app::serve
