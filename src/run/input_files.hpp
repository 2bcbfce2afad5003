#pragma once
// The files a run read, by identity (device and inode), so that an output
// is never renamed over one of them: the paths a program names (L sub.nc,
// L CYCLE [NAME=...]) are known only once it has run, and a link or a
// second name of the same file must count too (issue 26, finding 2).
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace nck::app {

class InputFiles {
 public:
  // `what` names the file in a message ("the subroutine sub.nc"); a path
  // that is no regular file (or is gone) is left out.
  void add(const std::string& path, std::string what);
  // Every regular file under `folder` (the machine folder).
  void add_folder(const std::string& folder, const std::string& what_prefix);
  // What the regular file `path` is, if it is one of them.
  std::optional<std::string> find(const std::string& path) const;

 private:
  struct Entry {
    dev_t dev;
    ino_t ino;
    std::string what;
  };
  std::vector<Entry> files_;
};

}  // namespace nck::app
