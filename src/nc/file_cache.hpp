#pragma once
// Program structure of a file (its %L / % sections) and the cache of called
// subprogram files (FCT_USE_CACHED_FILES): whole file texts with their
// section index, bounded by a file count and a total size, least recently
// used dropped first, re-read when the file's size or mtime changes.
#include <cstdint>
#include <filesystem>
#include <list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "source_reader.hpp"

namespace nck::nc::detail {

struct Section {
  bool local = false;   // %L name
  std::string name;     // upper case
  SourcePos header;     // the % line
  SourcePos body;       // the line after it
};

struct ProgramIndex {
  std::vector<Section> sections;
  // The first block outside comments when no % header comes before it: the
  // file is then an unnamed main program from its first line (TF5200,
  // diagnosis 20193: the main program starts at the first character outside
  // comments that is neither a blank nor '%').
  std::optional<SourcePos> first_code;
  const Section* main() const;
  const Section* local(const std::string& name_upper) const;
  // Where the file's program starts: its first line when code comes before
  // any header (or there is no header at all), else after the first %name;
  // nullopt when the file holds only %L local subroutines.
  std::optional<SourcePos> program_start() const;
};

// A "#COMMENT BEGIN" / "#COMMENT END" block (which = "BEGIN" / "END"; an
// N number may precede it): the position after the phrase, or npos.
std::size_t comment_phrase_end(std::string_view block, std::string_view which);

// The whole file of `size` bytes, or nullptr when it cannot be read.
std::shared_ptr<const std::string> read_text(const std::filesystem::path& p, std::uintmax_t size);

// Scans a reader from its current position to the end for section headers
// and the first code before them (a % line inside #COMMENT BEGIN .. END is
// no header; a ( ) comment may stand before the %, as the decoder reads it).
ProgramIndex scan_sections(SourceReader& r, std::size_t max_chars);
// Name of a "%L name" / "%name" header (comments stripped, upper case).
bool parse_header(std::string_view text, bool& local, std::string& name);

class FileCache {
 public:
  struct Entry {
    std::shared_ptr<const std::string> text;
    std::shared_ptr<const ProgramIndex> index;
  };
  FileCache(bool enabled, std::uint32_t max_files, std::uint32_t max_kb)
      : enabled_(enabled), max_files_(max_files), max_bytes_(std::uint64_t{max_kb} * 1024) {}
  bool enabled() const { return enabled_ && max_files_ > 0; }
  // The cached (or freshly loaded and cached) file; nullptr when the file is
  // unreadable or too large to cache.
  std::shared_ptr<const Entry> get(const std::filesystem::path& p, std::size_t max_chars);
  std::uint64_t hits() const { return hits_; }
  std::uint64_t loads() const { return loads_; }

 private:
  struct Slot {
    std::string key;
    std::filesystem::file_time_type mtime;
    std::uintmax_t size = 0;
    std::shared_ptr<const Entry> entry;
  };
  bool enabled_;
  std::uint32_t max_files_;
  std::uint64_t max_bytes_;
  std::uint64_t bytes_ = 0;
  std::uint64_t hits_ = 0, loads_ = 0;
  std::list<Slot> slots_;  // front = most recently used
};

}  // namespace nck::nc::detail
