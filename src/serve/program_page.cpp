#include "nck/serve/program_page.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "nck/output/output_writers.hpp"

namespace nck::app::serve {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// `path` for reading when it is a regular file; null otherwise. The file may
// have been replaced since it was loaded: a link in its last part is not
// followed (O_NOFOLLOW), and a FIFO does not block open() (O_NONBLOCK) —
// that wait held the server's one thread, and every client with it.
File open_regular(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return nullptr;
  struct stat st {};
  std::FILE* f = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) ? ::fdopen(fd, "rb") : nullptr;
  if (!f) ::close(fd);
  return File(f);
}

// The next line of `in` without its end, at most `max_bytes` of it (the
// rest of a longer line is skipped); false at the end of the file.
bool next_line(std::FILE* in, std::string& line, std::size_t max_bytes) {
  line.clear();
  int c = getc_unlocked(in);
  if (c == EOF) return false;
  for (; c != EOF && c != '\n'; c = getc_unlocked(in))
    if (line.size() < max_bytes) line += static_cast<char>(c);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

}  // namespace

std::string program_page(std::size_t channel, const std::filesystem::path& path, std::size_t first_line,
                         std::size_t max_bytes, const std::filesystem::path& source) {
  std::string lines = "[";
  std::size_t line_no = 1;
  bool more = false;
  if (const File in = path.empty() ? nullptr : open_regular(source.empty() ? path : source)) {
    std::string line;
    for (; next_line(in.get(), line, kMaxShownLineBytes); ++line_no) {
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
