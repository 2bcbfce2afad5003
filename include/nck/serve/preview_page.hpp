#pragma once
// GET /api/v1/preview: the loaded program's path before cycle start, as
// the pre-flight check plans it (issue 48 item 6; docs/api.md). At most
// prep::PathPreview::kMaxPoints points (some 6 MB of JSON); `cut` says the
// program goes on beyond them.
#include <cstddef>
#include <filesystem>
#include <string>

#include "nck/config/machine.hpp"

namespace nck::app::serve {

// The JSON answer for channel `channel` (1-based) of machine m and its
// program `path` (empty: none loaded): {"channel", "file", "points",
// "cut", "x", "y", "z" (machine coordinates), "px", "py", "pz" (program
// coordinates), "line", "rapid"}.
std::string preview_page(const config::Machine& m, std::size_t channel, const std::filesystem::path& path);

}  // namespace nck::app::serve
