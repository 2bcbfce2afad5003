#include "nck/serve/preview_page.hpp"

#include <fmt/format.h>

#include "nck/output/output_writers.hpp"
#include "nck/prep/path_preview.hpp"
#include "nck/prep/program_check.hpp"
#include "nck/report/report_series.hpp"
#include "nck/serve/live_path.hpp"

namespace nck::app::serve {
namespace {

template <class F>
std::string array_of(const std::vector<prep::PreviewPoint>& points, F&& item) {
  std::string s = "[";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) s += ',';
    item(s, points[i]);
  }
  s += ']';
  return s;
}

}  // namespace

std::string preview_page(const config::Machine& m, std::size_t channel, const std::filesystem::path& path) {
  prep::PathPreview preview(hmi_axes(m.channels[channel - 1]));
  if (!path.empty()) (void)prep::check_program(m, channel - 1, path, {.preview = &preview});
  const std::vector<prep::PreviewPoint>& pts = preview.points();
  std::string s = fmt::format(R"({{"channel":{},"file":{},"points":{},"cut":{})", channel,
                              json_quoted(path.filename().string()), pts.size(), preview.full());
  for (std::size_t k = 0; k < 3; ++k) {
    s += fmt::format(R"(,"{}":)", "xyz"[k]);
    s += array_of(pts, [k](std::string& o, const prep::PreviewPoint& p) { append_number(o, p.mcs[k], 4); });
    s += fmt::format(R"(,"p{}":)", "xyz"[k]);
    s += array_of(pts, [k](std::string& o, const prep::PreviewPoint& p) { append_number(o, p.pcs[k], 4); });
  }
  s += R"(,"line":)" + array_of(pts, [](std::string& o, const prep::PreviewPoint& p) { o += fmt::format("{}", p.line); });
  s += R"(,"rapid":)" + array_of(pts, [](std::string& o, const prep::PreviewPoint& p) { o += p.rapid ? '1' : '0'; });
  s += '}';
  return s;
}

}  // namespace nck::app::serve
