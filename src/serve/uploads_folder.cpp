#include "nck/serve/uploads_folder.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <utility>

#include <fmt/format.h>

#include "nck/core/path_within.hpp"

namespace nck::app::serve {
namespace fs = std::filesystem;

namespace {

Diagnostic refused(const fs::path& dir, std::string why) {
  return make_diagnostic(ErrorId::ServeUploadsRefused, SourceLoc{dir.string(), 0, 0}, std::move(why));
}

// A file system of the kernel's own objects: writing there reaches no
// program folder but the system (/proc/self/..., /sys, device nodes).
bool pseudo_file_system(const fs::path& real) {
  for (const char* top : {"/proc", "/sys", "/dev"})
    if (path_within(top, real)) return true;
  constexpr long kProc = 0x9fa0, kSysfs = 0x62656572, kDevpts = 0x1cd1, kCgroup = 0x27e0eb, kCgroup2 = 0x63677270,
                 kDebugfs = 0x64626720, kTracefs = 0x74726163, kSecurityfs = 0x73636673;
  struct statfs st{};
  if (::statfs(real.c_str(), &st) != 0) return false;
  const long type = static_cast<long>(st.f_type);
  return type == kProc || type == kSysfs || type == kDevpts || type == kCgroup || type == kCgroup2 ||
         type == kDebugfs || type == kTracefs || type == kSecurityfs;
}

// The folder `real` is or contains one of `guarded`: its name, else "".
std::string guarded_inside(const fs::path& real, const std::vector<fs::path>& guarded) {
  for (const fs::path& g : guarded) {
    std::error_code ec;
    const fs::path c = fs::weakly_canonical(g, ec);
    if (!ec && path_within(real, c)) return c.string();
  }
  return {};
}

}  // namespace

std::expected<UploadsFolder, Diagnostic> UploadsFolder::create_private() {
  std::error_code ec;
  const fs::path tmp = fs::temp_directory_path(ec);
  std::string templ = ((ec ? fs::path("/tmp") : tmp) / "nck-serve-uploads-XXXXXX").string();
  if (::mkdtemp(templ.data()) == nullptr)  // a new folder, 0700, or none
    return std::unexpected(refused(templ, fmt::format("no uploads folder can be made: {}", std::strerror(errno))));
  return UploadsFolder(fs::canonical(templ, ec), true);
}

std::expected<UploadsFolder, Diagnostic> UploadsFolder::named(const fs::path& dir, const std::vector<fs::path>& guarded) {
  if (::mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST)
    return std::unexpected(refused(dir, fmt::format("--uploads {} cannot be made: {}", dir.string(), std::strerror(errno))));
  std::error_code ec;
  const fs::path real = fs::canonical(dir, ec);
  if (ec || !fs::is_directory(real, ec)) return std::unexpected(refused(dir, fmt::format("--uploads {} is no folder", dir.string())));
  if (pseudo_file_system(real))
    return std::unexpected(refused(dir, fmt::format("--uploads {} lies on a pseudo file system ({})", dir.string(), real.string())));
  if (const std::string g = guarded_inside(real, guarded); !g.empty())
    return std::unexpected(refused(dir, fmt::format("--uploads {} is or contains {}, which the machine or a program "
                                                    "reads: an upload could replace its files",
                                                    dir.string(), g)));
  return UploadsFolder(real, false);
}

UploadsFolder::UploadsFolder(UploadsFolder&& other) noexcept
    : path_(std::move(other.path_)), remove_at_end_(std::exchange(other.remove_at_end_, false)) {}

UploadsFolder::~UploadsFolder() {
  if (!remove_at_end_ || path_.empty()) return;
  std::error_code ec;
  fs::remove_all(path_, ec);  // links inside are removed, never followed
}

bool write_replacing(const fs::path& folder, std::string_view name, std::string_view text) {
  std::string part = (folder / ".upload-XXXXXX").string();  // hidden: never listed, never a name to load
  const int fd = ::mkostemp(part.data(), O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;
  bool ok = true;
  for (std::size_t done = 0; ok && done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    ok = n > 0;
    if (ok) done += static_cast<std::size_t>(n);
  }
  ok = ::close(fd) == 0 && ok;
  ok = ok && ::rename(part.c_str(), (folder / std::string(name)).c_str()) == 0;
  if (!ok) ::unlink(part.c_str());
  return ok;
}

}  // namespace nck::app::serve
