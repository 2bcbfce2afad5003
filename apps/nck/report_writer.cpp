#include "report_writer.hpp"

#include "nck/core/utf8.hpp"
#include "output_file.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "machine_names.hpp"
#include "output_writers.hpp"

namespace nck::app {
namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : to_utf8(s)) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// One plot: a polyline per series over time, with axes labelled by range.
std::string svg_plot(const std::string& title, const std::vector<double>& t,
                     const std::vector<const std::vector<double>*>& ys,
                     const std::vector<std::string>& names) {
  constexpr double W = 900, H = 260, L = 60, R = 150, T = 24, B = 30;
  static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  double lo = 0, hi = 0;
  bool first = true;
  for (const auto* y : ys)
    for (double v : *y) {
      lo = first ? v : std::min(lo, v);
      hi = first ? v : std::max(hi, v);
      first = false;
    }
  if (hi - lo < 1e-9) hi = lo + 1;
  const double t0 = t.empty() ? 0 : t.front(), t1 = t.empty() || t.back() <= t0 ? t0 + 1 : t.back();
  auto x_of = [&](double v) { return L + (v - t0) / (t1 - t0) * (W - L - R); };
  auto y_of = [&](double v) { return T + (hi - v) / (hi - lo) * (H - T - B); };
  std::string s = fmt::format(
      "<svg xmlns='http://www.w3.org/2000/svg' width='{}' height='{}' role='img' aria-label='{}'>"
      "<text x='{}' y='16' font-weight='bold'>{}</text>"
      "<rect x='{}' y='{}' width='{}' height='{}' fill='none' stroke='#999'/>"
      "<text x='4' y='{}'>{:.6g}</text><text x='4' y='{}'>{:.6g}</text>"
      "<text x='{}' y='{}'>{:.6g} s</text><text x='{}' y='{}' text-anchor='end'>{:.6g} s</text>",
      W, H, escape(title), L, escape(title), L, T, W - L - R, H - T - B, T + 10, hi, H - B, lo, L, H - 8,
      t0, W - R, H - 8, t1);
  for (std::size_t k = 0; k < ys.size(); ++k) {
    std::string pts;
    for (std::size_t i = 0; i < t.size() && i < ys[k]->size(); ++i)
      pts += fmt::format("{:.1f},{:.1f} ", x_of(t[i]), y_of((*ys[k])[i]));
    const char* c = colours[k % std::size(colours)];
    s += fmt::format("<polyline fill='none' stroke='{}' stroke-width='1.5' points='{}'/>", c, pts);
    s += fmt::format("<text x='{}' y='{}' fill='{}'>{}</text>", W - R + 10, T + 16 + 18.0 * static_cast<double>(k), c,
                     escape(names[k]));
  }
  return s + "</svg>";
}

}  // namespace

void ReportWriter::start(const config::Machine& m, std::vector<std::string> programs, bool enabled) {
  enabled_ = enabled;
  if (!enabled_) return;
  programs_ = std::move(programs);
  for (const std::string& name : path_axis_columns(m)) series_.push_back({name, "mm / deg", {}});
  for (const auto& ch : m.channels) axis_count_.push_back(ch.axes.size());
  const std::vector<SpindleName> spindles = machine_spindles(m);
  for (const SpindleName& s : spindles) series_.push_back({s.name + ".rpm", "rpm", {}});
  spindle_count_ = spindles.size();
  for (std::size_t c = 0; c < m.channels.size(); ++c)  // 3D distance control: sensor, offset, error
    if (m.channels[c].dist_ctrl_enabled()) {
      dist_channels_.push_back(c);
      for (const char* n : {"dist.sensor", "dist.offset", "dist.error"}) series_.push_back({n, "mm", {}});
    }
}

void ReportWriter::sample(const kernel::TickOutput& out) {
  if (!enabled_) return;
  if (cycle_++ % stride_ != 0) return;
  if (t_.size() >= kMaxPoints) {  // thin out: keep every 2nd sample, sample half as often
    auto thin = [](auto& v) {
      std::size_t k = 0;
      for (std::size_t i = 0; i < v.size(); i += 2) v[k++] = v[i];
      v.resize(k);
    };
    thin(t_);
    for (Series& s : series_) thin(s.values);
    stride_ *= 2;
  }
  t_.push_back(out.t_s);
  std::size_t k = 0;
  for (std::size_t c = 0; c < axis_count_.size(); ++c)
    for (std::size_t j = 0; j < axis_count_[c]; ++j) series_[k++].values.push_back(out.channels[c].axis_mcs[j]);
  for (std::size_t s = 0; s < spindle_count_; ++s) series_[k++].values.push_back(out.spindles[s].set_rpm);
  for (std::size_t c : dist_channels_) {
    series_[k++].values.push_back(out.channels[c].dist_sensor_mm);
    series_[k++].values.push_back(out.channels[c].dist_offset_mm);
    series_[k++].values.push_back(out.channels[c].dist_error_mm);
  }
}

void ReportWriter::event(const std::string& json_line, bool is_error) {
  if (!enabled_) return;
  if (is_error) errors_.push_back(json_line);
  if (events_.size() < kMaxEvents) events_.push_back(json_line);
  else ++events_dropped_;
}

std::optional<std::string> ReportWriter::write(const std::string& path, double end_s, int exit_code) const {
  if (!enabled_) return std::nullopt;
  OutputFile f;
  if (auto err = f.open(path)) return err;
  std::string h =
      "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'><title>nck run report</title>"
      "<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}"
      "td,th{border:1px solid #ccc;padding:2px 6px;font-size:12px}pre{font-size:12px}"
      ".err{color:#b00}</style></head><body><h1>nck run report</h1>";
  h += "<table><tr><th>program(s)</th><td>";
  for (const std::string& p : programs_) h += escape(p) + "<br>";
  h += fmt::format("</td></tr><tr><th>simulated time</th><td>{:.3f} s</td></tr>"
                   "<tr><th>exit code</th><td>{}</td></tr><tr><th>errors</th><td>{}</td></tr></table>",
                   end_s, exit_code, errors_.size());
  if (!errors_.empty()) {
    h += "<h2 class='err'>Errors</h2><pre class='err'>";
    for (const std::string& e : errors_) h += escape(e) + "\n";
    h += "</pre>";
  }
  h += "<h2>Path axes (machine coordinates)</h2>";
  std::size_t k = 0;
  for (std::size_t c = 0; c < axis_count_.size(); ++c) {
    std::vector<const std::vector<double>*> ys;
    std::vector<std::string> names;
    for (std::size_t j = 0; j < axis_count_[c]; ++j, ++k) {
      ys.push_back(&series_[k].values);
      names.push_back(series_[k].name);
    }
    if (!ys.empty()) h += svg_plot(fmt::format("channel {}", c + 1), t_, ys, names) + "<br>";
  }
  if (spindle_count_ > 0) {
    std::vector<const std::vector<double>*> ys;
    std::vector<std::string> names;
    for (std::size_t s = 0; s < spindle_count_; ++s, ++k) {
      ys.push_back(&series_[k].values);
      names.push_back(series_[k].name);
    }
    h += "<h2>Spindles</h2>" + svg_plot("set-point speed (rpm)", t_, ys, names);
  }
  for (std::size_t c : dist_channels_) {
    std::vector<const std::vector<double>*> ys;
    std::vector<std::string> names;
    for (int i = 0; i < 3; ++i, ++k) {
      ys.push_back(&series_[k].values);
      names.push_back(series_[k].name);
    }
    h += fmt::format("<h2>3D distance control, channel {}</h2>", c + 1) +
         svg_plot("sensor, offset, distance error (mm)", t_, ys, names);
  }
  h += fmt::format("<h2>Events</h2><pre>");
  for (const std::string& e : events_) h += escape(e) + "\n";
  if (events_dropped_ > 0) h += fmt::format("... {} more events (see --events)\n", events_dropped_);
  h += "</pre></body></html>\n";
  f.write(h);
  return f.commit();
}

}  // namespace nck::app
