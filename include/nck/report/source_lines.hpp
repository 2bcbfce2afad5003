#pragma once
// The text of a program's lines for the report (tables, hovers, the G words
// of the block in execution), without keeping the file in memory: a
// 5-million-line program held line by line cost about 150 MB. One pass
// notes the byte offset of every kStride-th line; a line is read from the
// nearest one, and a small cache keeps the lines of a loop body at hand.
#include <array>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace nck::app {

class SourceLines {
 public:
  explicit SourceLines(std::string path);
  const std::string& name() const { return name_; }
  // Line n (1-based) without its line break ("" when there is none); opens
  // the file when it is closed.
  const std::string& line(std::uint32_t n);
  bool is_open() const { return in_.is_open(); }
  void close();  // the cache stays

  static constexpr std::uint32_t kStride = 64;      // lines between two noted offsets
  static constexpr std::size_t kCacheLines = 256;   // direct-mapped by line number

 private:
  bool read_line(std::string& out);  // the next line of the stream

  struct Cached {
    std::uint32_t line = 0;
    std::string text;
  };
  std::string name_;
  std::ifstream in_;
  std::vector<std::uint64_t> offsets_;  // of lines 1, 1 + kStride, 1 + 2 kStride ...
  std::uint32_t line_count_ = 0;
  std::uint32_t next_ = 0;  // the line the stream reads next (0: unknown)
  std::array<Cached, kCacheLines> cache_;
};

}  // namespace nck::app
