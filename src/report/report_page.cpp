// ReportWriter's output: the run's data as one JSON object, put into the
// page template (web/report.html) with the scripts and styles inlined.
#include <algorithm>
#include <utility>
#include <cmath>
#include <filesystem>
#include <set>
#include <fmt/format.h>

#include "nck/core/utf8.hpp"
#include "nck/core/version.hpp"
#include "nck/output/output_file.hpp"
#include "nck/output/output_writers.hpp"
#include "nck/report/embedded_files.hpp"
#include "nck/report/report_writer.hpp"

namespace nck::app {
namespace {

using json = nlohmann::ordered_json;
using LineRef = std::pair<std::uint16_t, std::uint32_t>;

constexpr std::size_t kMaxSummaryBlocks = 300;    // the longest blocks in the table
// The "lines" object (NC texts for hovers, tables and the program panel),
// JSON bytes: 1.5 MiB since the 3D view's 0.55 MB bundle joined the page
// (was 2 MiB of text, i.e. about 2.2 MB of JSON).
constexpr std::size_t kMaxLinesJsonBytes = 1536 << 10;
constexpr std::uint32_t kContextLines = 2;           // lines around each line shown, for the program panel

// "</" inside the data would end the <script> element that carries it.
std::string script_safe(std::string s) {
  if (s.find("</") == std::string::npos) return s;  // no second copy of megabytes
  std::string out;
  out.reserve(s.size() + s.size() / 64);
  std::size_t from = 0;
  for (std::size_t p = s.find("</"); p != std::string::npos; p = s.find("</", p + 2)) {
    out.append(s, from, p - from);
    out += "<\\/";
    from = p + 2;
  }
  out.append(s, from);
  return out;
}

// A piece of the page's data, made script-safe, onto the page.
void put(OutputFile& f, std::string piece) { f.write(script_safe(std::move(piece))); }

// Writes the template with each /*NAME*/ replaced once by its text; the
// parts come in template order and each search starts after the key found
// before, so inserted text is never searched. Written piece by piece: the
// page is MBs, and a whole copy of it would be the run's peak memory.
void write_filled(OutputFile& f, std::string_view page, const std::vector<std::pair<std::string, std::string>>& parts) {
  std::size_t from = 0;
  for (const auto& [key, text] : parts) {
    const std::size_t p = page.find(key, from);
    if (p == std::string::npos) continue;
    f.write(page.substr(from, p - from));
    f.write(text);
    from = p + key.size();
  }
  f.write(page.substr(from));
}

std::string html_text(const std::string& s) {
  std::string out;
  for (char c : to_utf8(s))
    out += c == '<' ? std::string("&lt;") : c == '&' ? std::string("&amp;") : c == '"' ? std::string("&quot;") : std::string(1, c);
  return out;
}

}  // namespace

void ReportWriter::write_channels(OutputFile& f, std::vector<LineRef>& lines_used) const {
  std::string s = "[";
  for (std::size_t c = 0; c < channels_.size(); ++c) {
    const Channel& ch = channels_[c];
    const ReportPlots::Channel& plot = plots_->channel(c);
    const TimedPath& path = plot.path;
    // Every cycle's position within a tenth of the DRO's digit while there
    // are at most kMaxBackplotPoints vertices; a coarser bound beyond.
    const TimedPath::Vertices v = path.vertices(kMaxBackplotPoints);
    const std::span<const TimedPoint> pts = v.points;
    const bool has_y = ch.axis[1] >= 0;
    const char* plane = ch.plane == 18 || (ch.plane == 0 && !has_y) ? "XZ" : ch.plane == 19 ? "YZ" : "XY";
    s += fmt::format(R"({}{{"n":{},"plane":"{}","axes":[{},{},{}],"has":[{},{},{}],"min":[)", c > 0 ? "," : "", c + 1,
                     plane, json_quoted(ch.axis_name[0]), json_quoted(ch.axis_name[1]), json_quoted(ch.axis_name[2]), ch.axis[0] >= 0,
                     ch.axis[1] >= 0, ch.axis[2] >= 0);
    for (int a = 0; a < 3; ++a) {
      if (a > 0) s += ',';
      append_number(s, path.empty() ? 0 : path.min()[a], 4);
    }
    s += "],\"max\":[";
    for (int a = 0; a < 3; ++a) {
      if (a > 0) s += ',';
      append_number(s, path.empty() ? 0 : path.max()[a], 4);
    }
    s += "]";
    // how far from the trace the cursor's interpolation may be, and whether each segment lies in one block
    s += ",\"path_error_mm\":";
    append_number(s, v.error_mm + 5e-5, 5);  // + the rounding to 4 decimals
    s += fmt::format(",\"path_by_block\":{}", v.by_block);
    put(f, std::exchange(s, std::string()));  // the point arrays one by one: each is up to a megabyte
    for (int a = 0; a < 3; ++a)
      put(f, fmt::format(",\"{}\":", "xyz"[a]) +
                 array_of(pts, [a](std::string& o, const TimedPoint& p) { append_number(o, p.pos[a], 4); }));
    put(f, ",\"line\":" + array_of(pts, [](std::string& o, const TimedPoint& p) { o += fmt::format("{}", p.line); }));
    put(f, ",\"file\":" + array_of(pts, [](std::string& o, const TimedPoint& p) { o += fmt::format("{}", p.file); }));
    put(f, ",\"rapid\":" + array_of(pts, [](std::string& o, const TimedPoint& p) { o += p.rapid ? '1' : '0'; }));
    put(f, ",\"t\":" + array_of(pts, [](std::string& o, const TimedPoint& p) { append_number(o, p.t_s, 6); }));
    if (ch.frames.size() > 1)  // which map each point is in; all the first one otherwise
      put(f, ",\"frame\":" + array_of(pts, [](std::string& o, const TimedPoint& p) { o += fmt::format("{}", p.frame); }));
s += ",\"cause_t\":" + array_of(plot.cause_t, [](std::string& o, double t) { append_number(o, t, 4); });
    s += ",\"cause\":" + array_of(plot.cause_name, [](std::string& o, const std::string& n) { o += json_quoted(n); });
    s += ",\"limits\":" + limits_json(ch);
    s += ",\"frames\":" + frames_json(ch);
    s += ",\"contour\":" + contour_json(ch);
    s += "}";
    for (const TimedPoint& p : pts) lines_used.emplace_back(p.file, p.line);
  }
  s += ']';
  put(f, std::move(s));
}

// The software limits of X, Y, Z (machine coordinates, mm; null where the
// channel has no such axis): the 3D view's box.
std::string ReportWriter::limits_json(const Channel& ch) const {
  std::string s;
  for (const auto* side : {&ch.limits.min_mm, &ch.limits.max_mm}) {
    s += side == &ch.limits.min_mm ? "{\"min\":[" : "],\"max\":[";
    for (int a = 0; a < 3; ++a) {
      if (a > 0) s += ',';
      if (ch.axis[a] < 0) s += "null";
      else append_number(s, (*side)[a], 4);
    }
  }
  s += "]}";
  return s;
}

// The channel's program -> machine maps: MCS = r * PCS + s on X, Y, Z
// (r row by row); none recorded: the identity.
std::string ReportWriter::frames_json(const Channel& ch) const {
  if (ch.frames.empty()) return R"([{"r":[1,0,0,0,1,0,0,0,1],"s":[0,0,0]}])";
  return array_of(ch.frames, [&](std::string& o, const Frame& frame) {
    const kernel::AffineMap& f = frame.map;
    std::array<int, 3> row{};  // the map's main-axis slot of the report's X, Y, Z
    for (int a = 0; a < 3; ++a) {
      row[a] = -1;
      for (int k = 0; k < 3; ++k)
        if (ch.axis[a] >= 0 && f.main[k] == ch.axis[a]) row[a] = k;
    }
    o += "{\"r\":[";
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        if (a + b > 0) o += ',';
        const bool both = row[a] >= 0 && row[b] >= 0;
        append_number(o, both ? f.rot[row[a]][row[b]] : a == b ? 1.0 : 0.0, 9);
      }
    o += "],\"s\":[";
    for (int a = 0; a < 3; ++a) {
      if (a > 0) o += ',';
      append_number(o, ch.axis[a] >= 0 ? f.shift[static_cast<std::size_t>(ch.axis[a])] : 0.0, 4);
    }
    o += "]";
    if (frame.diameter_slot >= 0) o += fmt::format(",\"diameter\":{}", frame.diameter_slot);  // ⌀ in the player's DRO
    o += "}";
  });
}

// The programmed contour of the G41/G42 stretches: one polyline each, in
// machine ("x","y","z") and program ("px","py","pz") coordinates, and the
// lines of its first and last block.
std::string ReportWriter::contour_json(const Channel& ch) const {
  if (!ch.contour) return "[]";
  return array_of(ch.contour->runs(), [](std::string& o, const ContourRun& run) {
    o += fmt::format(R"({{"lines":[{},{}])", run.first_line, run.last_line);
    for (int a = 0; a < 6; ++a) {
      o += fmt::format(",\"{}{}\":", a < 3 ? "" : "p", "xyz"[a % 3]);
      o += array_of(run.points, [a](std::string& t, const ContourPoint& p) {
        append_number(t, a < 3 ? p.mcs[a] : p.pcs[a - 3], 4);
      });
    }
    o += "}";
  });
}

std::string ReportWriter::summary_json(std::vector<LineRef>& lines_used) const {
  auto blocks = blocks_;
  // in the lines' order first, as the std::map this ledger was gave them:
  // the unstable sort by time then orders equal times as it did (the page
  // stays byte for byte the same)
  std::sort(blocks.begin(), blocks.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::sort(blocks.begin(), blocks.end(), [](const auto& a, const auto& b) { return a.second.time_s > b.second.time_s; });
  const std::size_t listed = std::min(blocks.size(), kMaxSummaryBlocks);
  std::string s = "{\"blocks\":[";
  for (std::size_t i = 0; i < listed; ++i) {
    const auto& [key, acc] = blocks[i];
    const auto& [c, file, line] = key;
    s += fmt::format(R"({}{{"ch":{},"file":{},"line":{},"count":{},"time_s":)", i > 0 ? "," : "", c + 1, file, line,
                     acc.count);
    append_number(s, acc.time_s, 4);
    s += "}";
    lines_used.emplace_back(file, line);
  }
  s += fmt::format("],\"blocks_total\":{},\"tools\":[", block_lines_);
  bool first = true;
  for (const auto& [key, acc] : tools_) {
    s += fmt::format(R"({}{{"ch":{},"tool":{},"count":{},"time_s":)", first ? "" : ",", key.first + 1,
                     json_quoted(key.second), acc.count);
    append_number(s, acc.time_s, 4);
    s += "}";
    first = false;
  }
  s += "]}";
  return s;
}

// The page's data, written piece by piece (a whole copy of its megabytes
// would be the run's peak memory), each made script-safe.
void ReportWriter::write_data(OutputFile& f, double end_s, int exit_code) const {
  std::vector<LineRef> lines_used;
  std::string s = "{\"meta\":{";
  s += fmt::format(R"("nck":{},"machine":{},"plc":{},"programs":{},"end_s":)", json_quoted(std::string(version())),
                   json_quoted(machine_), json_quoted(plc_),
                   array_of(programs_, [](std::string& o, const std::string& p) { o += json_quoted(p); }));
  append_number(s, end_s, 4);
  s += fmt::format(R"(,"exit_code":{},"end":{},"cycle_s":{},"errors":{},"warnings":{},"stride":{},"c_axis":{}}})",
                   exit_code, json_quoted(end_reason_), cycle_s_, errors_, warnings_, plots_->series().stride(), c_axis_used_);
  put(f, std::move(s));
  put(f, ",\"files\":" + array_of(files_, [](std::string& o, const SourceLines& file) { o += json_quoted(file.name()); }));
  put(f, ",\"spindles\":" + array_of(spindles_, [](std::string& o, const std::string& n) { o += json_quoted(n); }));
  put(f, ",\"series\":" + array_of(series_meta_, [](std::string& o, const std::string& m) { o += m; }));
  put(f, ",\"ts\":" + plots_->series().json(decimals_));
  put(f, ",\"channels\":");
  write_channels(f, lines_used);
  put(f, ",\"waits\":" + array_of(waits_, [&](std::string& o, const Wait& w) {
    o += fmt::format(R"({{"ch":{},"t0":{},"t1":{},"reason":{},"fn":{},"spindle":{},"sync":{},"file":{},"line":{}}})",
                     w.ch, w.t0, w.t1 < 0 ? end_s : w.t1, json_quoted(w.reason), json_quoted(w.fn), json_quoted(w.spindle),
                     json_quoted(w.sync), w.file, w.line);
    lines_used.emplace_back(w.file, w.line);
  }));
  put(f, ",\"marks\":" + array_of(marks_, [](std::string& o, const Mark& m) {
    o += fmt::format(R"({{"t":{},"spindle":{},"ch":{},"kind":{},"text":{}}})", m.t, m.ch ? -1 : static_cast<int>(m.spindle),
                     m.ch, json_quoted(m.kind), json_quoted(m.text));
  }));
  put(f, ",\"diagnostics\":" + array_of(diagnostics_, [](std::string& o, const std::string& l) { o += l; }));
  put(f, ",\"events\":" + array_of(events_, [](std::string& o, const std::string& l) { o += l; }));
  put(f, fmt::format(",\"events_dropped\":{}", events_dropped_));
  put(f, ",\"summary\":" + summary_json(lines_used));
  put(f, ",\"causes\":" + causes_json_);
  put(f, ",\"ghost\":" + ghost_json_);
  lines_used.insert(lines_used.end(), cause_lines_.begin(), cause_lines_.end());
  // the NC text of every line a hover or table shows
  for (const std::string& d : diagnostics_) {
    const json j = json::parse(d, nullptr, false);
    if (!j.is_object() || !j.contains("file") || !j["file"].is_string() || !j.contains("line")) continue;
    if (auto it = file_ids_.find(j["file"].get<std::string>()); it != file_ids_.end() && j["line"].is_number())
      lines_used.emplace_back(it->second, j["line"].get<std::uint32_t>());
  }
  std::sort(lines_used.begin(), lines_used.end());
  lines_used.erase(std::unique(lines_used.begin(), lines_used.end()), lines_used.end());
  put(f, ",\"lines\":" + lines_json(lines_used));
  put(f, "}");
}

// The NC text of the lines shown (hovers, tables, the program panel's
// current line), then of their neighbours for the program panel: first
// every line's next ones (±1), then ±2, so that a long program keeps the
// nearest context everywhere rather than all of it in its first part. The
// page's bytes are bounded (the panel shows "line N, text not embedded"
// for the rest).
std::string ReportWriter::lines_json(const std::vector<LineRef>& lines_used) const {
  std::string s = "{";
  bool full = false;  // the first line that does not fit ends the list
  std::set<LineRef> put_already;
  const auto put = [&](std::uint16_t file, std::uint32_t line) {
    if (full || !put_already.insert({file, line}).second) return;
    const std::string& text = line_text(file, line);
    if (text.empty()) return;
    const std::string entry = fmt::format("{}\"{}:{}\":{}", s.size() > 1 ? "," : "", file, line, json_quoted(text));
    full = s.size() + entry.size() > kMaxLinesJsonBytes;
    if (!full) s += entry;
  };
  for (const auto& [file, line] : lines_used) put(file, line);
  for (std::uint32_t d = 1; d <= kContextLines && !full; ++d)
    for (const auto& [file, line] : lines_used) {
      if (line > d) put(file, line - d);
      put(file, line + d);
    }
  s += '}';
  return s;
}

// Coupling periods from the link events: an "on" opens one, the "off" of
// the same channel and group closes it.
void ReportWriter::note_link(const kernel::Event& e, const kernel::LinkEvent& link, const RunNames& names) {
  const int ch = e.channel, group = link.group;
  if (link.on) {
    std::string pairs;  // "Y2 ← Y1, S2 ← S1": as the event table writes a link's pairs
    for (const auto& [slave, master] : names.link(link.payload).pairs)
      pairs += (pairs.empty() ? "" : ", ") + slave + " \u2190 " + master;
    if (links_.size() < kMaxListed) links_.push_back({ch, group, pairs, e.t_s, -1, ""});
    return;
  }
  for (LinkPeriod& p : links_)
    if (p.ch == ch && p.group == group && p.off_s < 0) {
      p.off_s = e.t_s;
      p.reason = kernel::link_reason_name(link.reason);
    }
}

std::string ReportWriter::link_table() const {
  if (links_.empty()) return {};
  std::string h = "<section><h2>Synchronous operation (coupling periods)</h2><table><tr><th>ch</th><th>group</th>"
                  "<th>pairs (slave ← master)</th><th>on (s)</th><th>off (s)</th><th>ended by</th></tr>";
  for (const LinkPeriod& p : links_)
    h += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{:.3f}</td><td>{}</td><td>{}</td></tr>", p.ch, p.group,
                     html_text(p.pairs), p.on_s, p.off_s < 0 ? std::string("still on") : fmt::format("{:.3f}", p.off_s),
                     html_text(p.reason));
  return h + "</table></section>";
}

std::optional<std::string> ReportWriter::write(const std::string& path, double end_s, int exit_code) {
  if (!enabled_) return std::nullopt;
  plots_->finish();
  OutputFile f;
  if (auto err = f.open(path)) return err;
  std::string title = "nck report";
  for (const std::string& p : programs_) title += " · " + std::filesystem::path(p).filename().string();
  // the data goes between the template's two halves
  constexpr std::string_view kDataKey = "/*NCK_DATA*/";
  const std::string_view page = embedded_file("report.html");
  const std::size_t data_at = std::min(page.find(kDataKey), page.size());
  write_filled(f, page.substr(0, data_at),
               {{"/*TITLE*/", html_text(title)},
                {"/*UPLOT_CSS*/", std::string(embedded_file("uPlot.min.css"))},
                {"/*REPORT_CSS*/", std::string(embedded_file("report.css"))},
                {"<!--LINK_TABLE-->", link_table()}});
  write_data(f, end_s, exit_code);
  write_filled(f, page.substr(std::min(data_at + kDataKey.size(), page.size())),
               {{"/*UPLOT_JS*/", std::string(embedded_file("uPlot.iife.min.js"))},
                {"/*BACKPLOT_JS*/", std::string(embedded_file("backplot.js"))},
                {"/*VIEW3D_JS*/", std::string(embedded_file("view3d.js"))},
                {"/*PLAYER_JS*/", std::string(embedded_file("player.js"))},
                {"/*TIMELINE_JS*/", std::string(embedded_file("timeline.js"))},
                {"/*REPORT_JS*/", std::string(embedded_file("report.js"))}});
  return f.commit();
}

}  // namespace nck::app
