#pragma once
// An output file of nck that is either complete or not there: a regular file
// is written to a temporary file beside it and renamed into place by
// commit(), so a failed run never leaves half a file where a good one was.
// "-" is stdout; FIFOs, devices and "live" outputs (--realtime) are written
// in place. Every write is checked; the first failure is kept with the OS's
// reason and reported by commit().
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace nck::app {

class OutputFile {
 public:
  OutputFile() = default;
  ~OutputFile();  // an uncommitted temporary is removed
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // The error text (with the OS reason) when it cannot be opened.
  std::optional<std::string> open(const std::string& path, bool live = false);
  bool is_open() const { return f_ != nullptr; }
  void write(std::string_view s);
  // Flushes, closes and renames into place; the error text, if any write,
  // the close or the rename failed (the target is then left as it was).
  std::optional<std::string> commit();
  // Drops what was written: the temporary is removed, the target left as it was.
  void discard();

 private:
  std::unique_ptr<char[]> buffer_;  // stdio's buffer of a temporary file (outlives f_)
  std::FILE* f_ = nullptr;
  std::string path_;  // the target
  std::string temp_;  // written here, renamed at commit (empty: in place)
  int error_ = 0;     // errno of the first failure
};

// Writes s to stdout without throwing; false when it could not be written
// (main_cli checks stdout once more when the command is done).
bool write_stdout(std::string_view s);

}  // namespace nck::app
