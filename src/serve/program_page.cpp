#include "nck/serve/program_page.hpp"

#include <fstream>

#include <fmt/format.h>

#include "nck/output/output_writers.hpp"

namespace nck::app::serve {
namespace {

// The next line of `in` without its end, at most `max_bytes` of it (the
// rest of a longer line is skipped); false at the end of the file.
bool next_line(std::istream& in, std::string& line, std::size_t max_bytes) {
  line.clear();
  if (in.peek() == std::char_traits<char>::eof()) return false;
  for (int c = in.get(); c != std::char_traits<char>::eof() && c != '\n'; c = in.get())
    if (line.size() < max_bytes) line += static_cast<char>(c);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

}  // namespace

std::string program_page(std::size_t channel, const std::filesystem::path& path, std::size_t first_line,
                         std::size_t max_bytes) {
  std::string lines = "[";
  std::size_t line_no = 1;
  bool more = false;
  if (!path.empty()) {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    for (; next_line(in, line, kMaxShownLineBytes); ++line_no) {
      if (line_no < first_line) continue;
      const std::string quoted = json_quoted(line);
      // the first line of a page always goes (it is at most kMaxShownLineBytes)
      if (line_no > first_line && lines.size() + quoted.size() + 1 > max_bytes) {
        more = true;
        break;
      }
      if (lines.size() > 1) lines += ',';
      lines += quoted;
    }
  }
  lines += ']';
  return fmt::format(R"({{"channel":{},"file":{},"path":{},"first_line":{},"lines":{},"next_line":{}}})", channel,
                     json_quoted(path.filename().string()), json_quoted(path.string()), first_line, lines,
                     more ? std::to_string(line_no) : "null");
}

}  // namespace nck::app::serve
