#pragma once
// Files built into the binary at build time (cmake/embed_files.cmake): the
// report's web files and uPlot ("report.html", "uPlot.iife.min.js", ...) and
// the example machine folders that `nck init` writes ("examples/mill/x.lis").
#include <span>
#include <string_view>

namespace nck::app {

struct EmbeddedFile {
  std::string_view name;
  std::string_view content;  // the bytes as in the file
};

std::span<const EmbeddedFile> embedded_files();
// The content of the file of that name; empty when there is none.
std::string_view embedded_file(std::string_view name);

}  // namespace nck::app
