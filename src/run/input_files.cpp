#include "input_files.hpp"

#include <filesystem>
#include <sys/stat.h>

namespace nck::app {

void InputFiles::add(const std::string& path, std::string what) {
  struct stat st{};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return;
  for (const Entry& e : files_)
    if (e.dev == st.st_dev && e.ino == st.st_ino) return;
  files_.push_back(Entry{st.st_dev, st.st_ino, std::move(what)});
}

void InputFiles::add_folder(const std::string& folder, const std::string& what_prefix) {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    add(it->path().string(), what_prefix + it->path().string());
}

std::optional<std::string> InputFiles::find(const std::string& path) const {
  struct stat st{};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  for (const Entry& e : files_)
    if (e.dev == st.st_dev && e.ino == st.st_ino) return e.what;
  return std::nullopt;
}

}  // namespace nck::app
