#include "nck/serve/api_pages.hpp"

#include <cmath>
#include <cstdlib>

#include "nck/config/parameter_registry.hpp"
#include "nck/core/version.hpp"
#include "nck/output/diagnostic_json.hpp"
#include "nck/output/output_writers.hpp"
#include "nck/report/backplot_axes.hpp"
#include "nck/report/embedded_files.hpp"
#include "nck/serve/access.hpp"

namespace nck::app::serve {

using json = nlohmann::ordered_json;

HttpReply ok_json(const json& j) { return HttpReply{200, "application/json", dump_json(j), {}}; }

std::optional<HttpReply> page_file(std::string_view path) {
  static constexpr std::pair<std::string_view, std::string_view> kFiles[] = {
      {"/", "hmi.html"},
      {"/hmi.js", "hmi.js"},
      {"/hmi.css", "hmi.css"},
      {"/hmi_ui.js", "hmi_ui.js"},
      {"/hmi_api.js", "hmi_api.js"},
      {"/hmi_program.js", "hmi_program.js"},
      {"/hmi_controls.js", "hmi_controls.js"},
      {"/hmi_channel.js", "hmi_channel.js"},
      {"/backplot.js", "backplot.js"},
      {"/hmi_offsets.js", "hmi_offsets.js"},
      {"/timeline.js", "timeline.js"},
      {"/uPlot.iife.min.js", "uPlot.iife.min.js"},
      {"/uPlot.min.css", "uPlot.min.css"}};
  for (const auto& [url, name] : kFiles) {
    if (path != url) continue;
    const std::string_view type = name.ends_with(".js")    ? "text/javascript; charset=utf-8"
                                  : name.ends_with(".css") ? "text/css; charset=utf-8"
                                                           : "text/html; charset=utf-8";
    HttpReply r{200, std::string(type), std::string(embedded_file(name)), {}};
    r.headers.emplace_back("Content-Security-Policy",
                           "default-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data:; "
                           "frame-ancestors 'none'");
    return r;
  }
  return std::nullopt;
}

json machine_json(const config::Machine& m) {
  json channels = json::array();
  for (const config::ChannelConfig& c : m.channels) {
    json axes = json::array(), spindles = json::array();
    for (const auto& a : c.axes) axes.push_back(a.name);
    for (const auto& s : c.spindles) spindles.push_back(s.name);
    json plot_axes = json::array();  // the backplot's X, Y, Z (null: none), as the report draws them
    for (const int j : backplot_axes(c)) plot_axes.push_back(j < 0 ? json() : json(c.axes[static_cast<std::size_t>(j)].name));
    channels.push_back({{"axes", std::move(axes)}, {"spindles", std::move(spindles)}, {"plot_axes", std::move(plot_axes)}});
  }
  return {{"api", 1}, {"cycle_time_s", m.cycle_time_us * 1e-6}, {"channels", std::move(channels)}};
}

json parameters_json() {
  json all = json::array();
  for (const config::ParamInfo& p : config::all_parameters()) {
    json j = {{"key", std::string(p.key)}, {"id", std::string(p.id)}, {"meaning", std::string(p.meaning)},
              {"unit", std::string(p.list_unit)}};
    if (std::isfinite(p.min)) j["min"] = p.min;
    if (std::isfinite(p.max)) j["max"] = p.max;
    all.push_back(std::move(j));
  }
  return all;
}

std::size_t channel_of(std::string_view target) {
  const std::string_view text = query_value(target, "channel");
  return text.empty() ? 1 : static_cast<std::size_t>(std::atoi(std::string(text).c_str()));
}

std::optional<HttpReply> fixed_answer(std::string_view path) {
  if (path == "/api/v1/errors") return ok_json(catalogue_json());
  if (path == "/api/v1/parameters") return ok_json(parameters_json());
  if (path == "/api/v1/openapi.json")  // docs/openapi.json, built in
    return HttpReply{200, "application/json", std::string(embedded_file("openapi.json")), {}};
  if (path == "/api/v1/version") return ok_json(json{{"nck", version()}, {"api", "v1"}, {"git", git_hash()}});
  return std::nullopt;
}

}  // namespace nck::app::serve
