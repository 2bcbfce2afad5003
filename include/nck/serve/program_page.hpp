#pragma once
// GET /api/v1/program: a loaded program's text as JSON lines, one page at a
// time (docs/api.md). The answer's own size is the bound, not the lines'
// bytes: a 4 MiB file of empty lines made 12.6 MB of JSON (and 391 MB of
// JSON values) when only the text was counted.
#include <cstddef>
#include <filesystem>
#include <string>

namespace nck::app::serve {

inline constexpr std::size_t kMaxProgramPageBytes = 2 * 1024 * 1024;  // one answer
inline constexpr std::size_t kMaxShownLineBytes = 64 * 1024;          // a longer line is cut there

// The JSON answer for channel `channel` (1-based) and its program `path`
// (empty: none loaded), lines from `first_line` (1-based) on, at most
// `max_bytes` long: {"channel", "file", "path", "first_line", "lines",
// "next_line"} (next_line: the first line not sent, or null at the end).
// The lines are read from `source` (default: `path`), and only when it is
// a regular file that is no symbolic link (else there are none).
std::string program_page(std::size_t channel, const std::filesystem::path& path, std::size_t first_line,
                         std::size_t max_bytes = kMaxProgramPageBytes, const std::filesystem::path& source = {});

}  // namespace nck::app::serve
