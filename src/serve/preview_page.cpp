#include "nck/serve/preview_page.hpp"

#include <fmt/format.h>

#include "nck/output/output_writers.hpp"
#include "nck/prep/path_preview.hpp"
#include "nck/prep/program_check.hpp"
#include "nck/serve/live_path.hpp"
#include "nck/serve/point_columns.hpp"

namespace nck::app::serve {

std::string preview_page(const config::Machine& m, std::size_t channel, const std::filesystem::path& path) {
  prep::PathPreview preview(backplot_axes(m.channels[channel - 1]));
  if (!path.empty()) (void)prep::check_program(m, channel - 1, path, {.preview = &preview});
  const std::vector<prep::PreviewPoint>& pts = preview.points();
  std::string s = fmt::format(R"({{"channel":{},"file":{},"points":{},"cut":{})", channel,
                              json_quoted(path.filename().string()), pts.size(), preview.full());
  append_point_columns(s, pts);
  s += '}';
  return s;
}

}  // namespace nck::app::serve
