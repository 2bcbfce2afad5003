#pragma once
// The report's template, script and styles, and uPlot, compiled into the
// binary (cmake/embed_web.cmake) so that `--report` writes one offline file.
#include <string_view>

namespace nck::app {

// The file's text by name ("report.html", "report.js", "report.css",
// "uPlot.iife.min.js", "uPlot.min.css"); empty when there is no such asset.
std::string_view web_asset(std::string_view name);

}  // namespace nck::app
