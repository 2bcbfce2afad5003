#pragma once
// Files of the source tree built into the binary (cmake/embed_files.cmake):
// the example machine folders that `nck init` writes.
#include <span>
#include <string_view>

namespace nck::app {

struct EmbeddedFile {
  std::string_view path;     // relative to the source tree: "examples/mill/x.lis"
  std::string_view content;  // the bytes as in the file
};

std::span<const EmbeddedFile> embedded_files();

}  // namespace nck::app
