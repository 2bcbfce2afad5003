#pragma once
// Incremental reading of an NC file, one block at a time. Physical lines
// ending in '\' are joined into one block. Only a fixed-size read buffer and
// the current block are kept, so memory stays bounded for any file size;
// a block's byte offset can be remembered and returned to (loops).
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "work_meter.hpp"

namespace nck::nc::detail {

struct SourcePos {
  std::uint64_t offset = 0;  // byte offset of the block's first line
  std::uint32_t line = 1;    // its 1-based line number
};

class SourceReader {
 public:
  SourceReader() = default;
  ~SourceReader();
  SourceReader(const SourceReader&) = delete;
  SourceReader& operator=(const SourceReader&) = delete;

  bool open_file(const std::filesystem::path& p);
  void open_memory(std::shared_ptr<const std::string> text);
  // Counts every block read against `m` (not owned; nullptr: none);
  // `first_pass_free`: blocks read for the first time are not counted (the
  // main program). Once the meter halts, read_block() reads nothing more.
  void set_meter(WorkMeter* m, bool first_pass_free) {
    meter_ = m;
    first_pass_free_ = first_pass_free;
  }

  // Reads the next block; false at end of file (or when the meter halts). The block text never holds
  // more than max_chars characters; block_too_long() tells if more were cut.
  bool read_block(std::size_t max_chars);
  const std::string& text() const { return text_; }
  bool block_too_long() const { return too_long_; }
  SourcePos block_pos() const { return block_pos_; }
  // Where reading continues (after the current block).
  SourcePos next_pos() const { return SourcePos{offset_, line_}; }
  void seek(SourcePos p);

  // Maps a byte position of the block text to line and 1-based column.
  void locate(std::size_t text_pos, std::uint32_t& line, std::uint32_t& column) const;

 private:
  bool read_next(std::size_t max_chars);  // read_block() without the meter
  bool next_line(std::size_t room);  // appends one physical line to text_
  bool fill();

  std::FILE* file_ = nullptr;
  std::shared_ptr<const std::string> mem_;
  std::vector<char> buf_;
  std::size_t buf_pos_ = 0, buf_len_ = 0;
  std::uint64_t buf_offset_ = 0;  // file offset of buf_[0]
  std::uint64_t offset_ = 0;      // file offset of the next unread byte
  std::uint32_t line_ = 1;        // line number of the next unread line
  bool eof_ = false;
  WorkMeter* meter_ = nullptr;
  bool first_pass_free_ = false;
  std::uint64_t first_pass_end_ = 0;  // offset up to which the file was read before

  std::string text_;
  bool too_long_ = false;
  SourcePos block_pos_;
  struct Segment {
    std::uint32_t text_pos;  // where the physical line starts in text_
    std::uint32_t line;
    std::uint32_t col0;      // column offset of that text in its line (0)
  };
  std::vector<Segment> segs_;
};

}  // namespace nck::nc::detail
