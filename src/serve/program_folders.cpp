#include "nck/serve/program_folders.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "nck/core/path_within.hpp"
#include "nck/serve/uploads_folder.hpp"

namespace nck::app::serve {
namespace fs = std::filesystem;

namespace {

Diagnostic refused(std::string_view name, std::string why) {
  return make_diagnostic(ErrorId::ApiProgramNotAllowed, SourceLoc{std::string(name.substr(0, 200)), 0, 0},
                         std::move(why));
}

fs::path canonical_or_empty(const fs::path& p) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(p, ec);
  return ec ? fs::path() : c;
}

bool plain_name(std::string_view name) {
  return !name.empty() && name.size() <= 64 && name.front() != '.' &&
         std::all_of(name.begin(), name.end(), [](char c) {
           return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' ||
                  c == '_' || c == '-';
         });
}

// What a machine folder holds besides programs: lists, scenarios, notes.
bool looks_like_program(const fs::path& p) {
  static constexpr std::string_view kOther[] = {".lis", ".plc", ".md", ".json", ".jsonl", ".csv", ".html",
                                                ".png", ".sha256", ".part"};
  const std::string ext = p.extension().string();
  return p.filename().string().front() != '.' && std::find(std::begin(kOther), std::end(kOther), ext) == std::end(kOther);
}

}  // namespace

ProgramFolders::ProgramFolders(std::vector<fs::path> roots, fs::path uploads, std::uintmax_t max_bytes)
    : max_bytes_(max_bytes) {
  uploads_ = canonical_or_empty(uploads);
  roots.push_back(uploads_);
  for (const fs::path& r : roots)
    if (fs::path c = canonical_or_empty(r); !c.empty() && std::find(roots_.begin(), roots_.end(), c) == roots_.end())
      roots_.push_back(c);
}

std::expected<fs::path, Diagnostic> ProgramFolders::resolve(std::string_view name) const {
  if (name.empty() || name.find('\0') != std::string_view::npos) return std::unexpected(refused(name, "no program named"));
  const fs::path given{std::string(name)};
  for (const fs::path& part : given)
    if (part == "..") return std::unexpected(refused(name, "'..' may not appear in a program name"));
  for (const fs::path& root : roots_) {
    const fs::path real = canonical_or_empty(given.is_absolute() ? given : root / given);
    if (real.empty() || !path_within(root, real)) continue;
    std::error_code ec;
    if (!fs::is_regular_file(real, ec)) continue;
    const std::uintmax_t size = fs::file_size(real, ec);
    if (ec || size > max_bytes_)
      return std::unexpected(refused(name, fmt::format("the program is larger than {} bytes", max_bytes_)));
    return real;
  }
  return std::unexpected(refused(name, "no such program inside the folders nck serve may read (--programs, the "
                                       "machine folder, uploads); a symbolic link out of them is refused"));
}

std::vector<std::string> ProgramFolders::list() const {
  std::vector<std::string> names;
  for (const fs::path& root : roots_) {
    std::error_code ec;
    for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end && names.size() < 1000; it.increment(ec)) {
      if (it.depth() > 3) it.disable_recursion_pending();
      if (!it->is_regular_file(ec) || !looks_like_program(it->path())) continue;
      std::string rel = it->path().lexically_relative(root).generic_string();
      if (std::find(names.begin(), names.end(), rel) == names.end() && resolve(rel)) names.push_back(std::move(rel));
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::expected<std::string, Diagnostic> ProgramFolders::save_upload(std::string_view name, std::string_view text) const {
  if (!plain_name(name))
    return std::unexpected(refused(name, "an uploaded program's name is 1 to 64 letters, digits, '.', '_' or '-' "
                                         "and does not start with '.'"));
  if (text.size() > max_bytes_)
    return std::unexpected(make_diagnostic(ErrorId::ApiTooLarge, SourceLoc{std::string(name), 0, 0},
                                           fmt::format("a program is at most {} bytes", max_bytes_)));
  if (uploads_.empty() || !write_replacing(uploads_, name, text))
    return std::unexpected(refused(name, "the uploads folder cannot be written"));
  return std::string(name);
}

bool ProgramFolders::upload_exists(std::string_view name) const {
  std::error_code ec;
  return plain_name(name) && !uploads_.empty() && fs::exists(fs::symlink_status(uploads_ / std::string(name), ec));
}

}  // namespace nck::app::serve
