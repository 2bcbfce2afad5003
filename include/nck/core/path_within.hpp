#pragma once
// Whether a file lies in a folder, for the places that only open files
// inside the folders they were given (the decoder's subprogram roots, the
// served programs' folders).
#include <algorithm>
#include <filesystem>

namespace nck {

// `p` lies in `root` (or is it): both canonical, compared part by part, so
// /a/bc is not in /a/b.
inline bool path_within(const std::filesystem::path& root, const std::filesystem::path& p) {
  const auto [end, _] = std::mismatch(root.begin(), root.end(), p.begin(), p.end());
  return end == root.end();
}

}  // namespace nck
