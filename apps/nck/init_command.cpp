// nck init DIR [--mill|--lathe]: a machine folder to start from, written from
// the example machines built into the binary (embedded_files.hpp).
#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "nck/core/diagnostic.hpp"
#include "nck/report/embedded_files.hpp"
#include "commands.hpp"

namespace nck::app {
namespace {

int fail(ErrorId id, const std::string& message) {
  fmt::print(stderr, "nck: error {}: {}\n", number(id), message);
  return 2;
}

}  // namespace

int init_machine(const InitOptions& opt) {
  namespace fs = std::filesystem;
  const fs::path dir = opt.folder;
  std::error_code ec;
  // Never overwrite someone's machine data: only a new or empty folder.
  if (fs::exists(dir, ec) && !(fs::is_directory(dir, ec) && fs::is_empty(dir, ec)))
    return fail(ErrorId::AppBadUsage, fmt::format("{} exists and is not an empty folder; nck init writes "
                                                  "only into a new or empty one", dir.string()));
  fs::create_directories(dir, ec);
  if (ec) return fail(ErrorId::AppOutputFile, fmt::format("cannot create {}: {}", dir.string(), ec.message()));
  const std::string prefix = fmt::format("examples/{}/", opt.lathe ? "lathe" : "mill");
  std::string program;
  std::size_t written = 0;
  for (const EmbeddedFile& f : embedded_files()) {
    if (!f.name.starts_with(prefix)) continue;
    const fs::path out = dir / f.name.substr(prefix.size());
    std::ofstream file(out, std::ios::binary);
    file.write(f.content.data(), static_cast<std::streamsize>(f.content.size()));
    file.close();
    if (!file) return fail(ErrorId::AppOutputFile, fmt::format("cannot write {}: {}", out.string(), std::strerror(errno)));
    if (out.extension() == ".nc") program = out.string();
    ++written;
  }
  fmt::print("wrote a {} machine ({} files) to {}\nnext: nck check {}\n      nck run {} {} --report run.html\n",
             opt.lathe ? "lathe" : "milling", written, dir.string(), dir.string(), dir.string(), program);
  return 0;
}

}  // namespace nck::app
