#include "nck/output/output_writers.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "nck/core/utf8.hpp"
#include "nck/distctrl/controller.hpp"
#include "nck/output/diagnostic_json.hpp"
#include "nck/output/machine_names.hpp"
#include "nck/spindle/spindle_status.hpp"

namespace nck::app {

using json = nlohmann::ordered_json;

nlohmann::ordered_json RunNames::spindle(std::optional<std::int8_t> index) const {
  const std::string* name = index && *index >= 0 && run ? run->spindle_name(static_cast<std::size_t>(*index)) : nullptr;
  if (!name) return nullptr;
  return *name;
}

nlohmann::ordered_json RunNames::axis(std::int8_t index) const {
  if (index < 0 || !run) return nullptr;
  return config::axis_list_name(run->config(), static_cast<std::size_t>(index));
}

std::string dump_json(const nlohmann::ordered_json& j, int indent) {
  // Every string put in is UTF-8 already (to_utf8); replacing is the backstop.
  return j.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

std::string json_quoted(std::string_view text) {
  std::string out;
  const auto plain = [](char c) {  // printable ASCII without '"' and '\\': as it is
    const auto u = static_cast<unsigned char>(c);
    return u >= 0x20 && u < 0x80 && c != '"' && c != '\\';
  };
  if (std::all_of(text.begin(), text.end(), plain)) {  // most NC lines
    out.reserve(text.size() + 2);
    out += '"';
    out += text;
    out += '"';
    return out;
  }
  const std::string utf8 = to_utf8(text);
  out.reserve(utf8.size() + 2);
  out += '"';
  for (const char c : utf8) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\t': out += "\\t"; break;
      case '\n': out += "\\n"; break;
      case '\f': out += "\\f"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", static_cast<unsigned>(c));
        else out += c;  // UTF-8 bytes pass through, as dump_json leaves them
    }
  }
  out += '"';
  return out;
}

std::string RunNames::text(ErrorId id, std::optional<std::uint32_t> message) const {
  if (message && run) return to_utf8(run->message(*message));
  const ErrorInfo* info = find_error(id);
  return info ? fmt::format("{}: {}", info->text, info->remedy) : std::string();
}

std::string RunNames::file(std::size_t ch, std::uint16_t id) const {
  const nc::Decoder* d = run ? run->decoder(ch) : nullptr;
  return d ? to_utf8(d->file_name(id)) : std::string();
}

std::optional<kernel::EventKind> event_kind_from(std::string_view name) {
  for (std::size_t k = 0; k < std::variant_size_v<kernel::EventPayload>; ++k)
    if (name == kernel::event_name(static_cast<kernel::EventKind>(k))) return static_cast<kernel::EventKind>(k);
  return std::nullopt;
}

void EventWriter::write_line(const std::string& line) {
  file_.write(line);
  file_.write("\n");
}

std::string EventWriter::line(const kernel::Event& e, const RunNames& names) { return dump_json(object(e, names)); }

const std::string& BlockEventText::quoted_file(std::size_t ch, std::uint16_t id, const RunNames& names) {
  const auto key = static_cast<std::uint32_t>(ch << 16 | id);
  for (const auto& [k, text] : files_)
    if (k == key) return text;
  files_.emplace_back(key, dump_json(json(names.file(ch, id))));
  return files_.back().second;
}

const std::string& BlockEventText::line(const kernel::Event& e, const RunNames& names) {
  std::string& s = line_;
  s.assign("{\"t\":");
  char num[64];
  // nlohmann's own number writer: the digits dump_json gives the same double
  if (std::isfinite(e.t_s)) s.append(num, nlohmann::detail::to_chars(num, num + sizeof num, e.t_s));
  else s += "null";
  if (e.channel > 0) {
    s += ",\"ch\":";
    s.append(num, std::to_chars(num, num + sizeof num, unsigned{e.channel}).ptr);
  }
  s += ",\"ev\":\"block\",\"line\":";
  s.append(num, std::to_chars(num, num + sizeof num, e.at.line).ptr);
  s += ",\"n\":";
  if (e.at.n) s.append(num, std::to_chars(num, num + sizeof num, *e.at.n).ptr);
  else s += "null";
  s += ",\"file\":";
  s += quoted_file(e.channel_index(), e.at.file_id, names);
  s += '}';
  return s;
}

namespace {
// A warning or error line is also the diagnostic's one shape (issue 47 item
// 5): its first fields (id, line, file, msg, beside t, ch, ev) stay, the
// others follow them.
void add_diagnosis_fields(nlohmann::ordered_json& j, const kernel::Event& e, const RunNames& names) {
  const kernel::ev::Diagnosis* d = e.get<kernel::ev::Warning>();
  if (!d) d = e.get<kernel::ev::Error>();
  if (!d) return;
  const SourceLoc loc{names.file(e.channel_index(), e.at.file_id), e.at.line, 0};
  std::string text = names.text(d->id, d->message);
  // A drive's diagnostic names its axis (CiA 402 drives, issue 46).
  if (d->axis && names.run) text += fmt::format(" (axis {})", config::axis_list_name(names.run->config(), static_cast<std::size_t>(*d->axis)));
  add_diagnostic_fields(j, diagnostic_json(d->id, text, loc, e.channel,
                                           e.get<kernel::ev::Warning>() ? Severity::warning : Severity::error));
  if (d->axis && names.run) j["axis"] = config::axis_list_name(names.run->config(), static_cast<std::size_t>(*d->axis));
}
}  // namespace

// The head's fields ("t", "ch", "ev" first, as docs/outputs.md lists them),
// then the payload's, by the writer beside its type.
nlohmann::ordered_json EventWriter::object(const kernel::Event& e, const RunNames& names) {
  json j;
  j["t"] = e.t_s;
  if (e.channel > 0) j["ch"] = e.channel;
  j["ev"] = kernel::event_name(e.kind());
  std::visit([&](const auto& payload) { write_json(j, payload, e, names); }, e.payload);
  add_diagnosis_fields(j, e, names);
  return j;
}


namespace {
bool has_dist_ctrl(const config::ChannelConfig& ch) {
  return ch.dist_ctrl_enabled();
}
}  // namespace

std::vector<std::string> TraceWriter::column_names(const config::Machine& m, TraceColumns extra) {
  std::vector<std::string> cols{"t"};
  for (const std::string& a : path_axis_columns(m)) cols.push_back(a);
  bool first = true;  // dist.offset, then 2.dist.offset ... for later channels
  for (std::size_t c = 0; c < m.channels.size(); ++c) {
    if (!has_dist_ctrl(m.channels[c])) continue;
    const std::string prefix = first ? std::string() : fmt::format("{}.", c + 1);
    cols.push_back(prefix + "dist.offset");
    cols.push_back(prefix + "dist.sensor");  // raw sensor value, mm
    cols.push_back(prefix + "dist.state");   // distctrl::State: 0 INACTIVE .. 5 ERROR
    first = false;
  }
  for (const SpindleName& s : machine_spindles(m)) {
    cols.push_back(s.name + ".rpm");
    cols.push_back(s.name + ".pos");
    cols.push_back(s.name + ".act_rpm");
    if (s.speed_controlled) cols.push_back(s.name + ".drive");  // drive output value (antr.v_reso_*)
  }
  for (std::size_t c = 0; c < m.channels.size(); ++c) {
    const std::string prefix = c == 0 ? std::string() : fmt::format("{}.", c + 1);
    if (extra.path_v) cols.push_back(prefix + "path.v");
    if (extra.path_a) cols.push_back(prefix + "path.a");
    if (extra.path_j) cols.push_back(prefix + "path.j");
  }
  return cols;
}

TraceLayout::TraceLayout(const config::Machine& m) {
  for (const auto& ch : m.channels) {
    axes_per_channel_.push_back(ch.axes.size());
    dist_ctrl_.push_back(has_dist_ctrl(ch));
  }
  for (const SpindleName& s : machine_spindles(m)) speed_controlled_.push_back(s.speed_controlled);
}

std::optional<std::string> TraceWriter::open(const std::string& path, bool live, const config::Machine& m,
                                             std::uint64_t every, TraceColumns extra) {
  if (auto err = file_.open(path, live)) return err;
  every_ = every == 0 ? 1 : every;
  layout_ = TraceLayout(m);
  extra_ = extra;
  path_.assign(extra.any() ? m.channels.size() : 0, PathDerivatives(m.cycle_time_us * 1e-6));
  std::string header;
  for (const std::string& c : column_names(m, extra)) header += (header.empty() ? "" : ",") + c;
  file_.write(to_utf8(header) + "\n");
  return std::nullopt;
}

void TraceWriter::write(std::uint64_t cycle, const kernel::TickOutput& out) {
  if (!file_.is_open()) return;
  for (std::size_t c = 0; c < path_.size(); ++c) path_[c].update(out.channels[c].path_velocity_mm_s);
  if (cycle % every_ != 0) return;
  row_.clear();
  bool first = true;
  layout_.visit(out, [&](double v, TraceLayout::Format f) {
    if (!first) row_ += ',';
    first = false;
    switch (f) {
      case TraceLayout::Format::mm: fmt::format_to(std::back_inserter(row_), "{:.6f}", v); break;
      case TraceLayout::Format::rpm: fmt::format_to(std::back_inserter(row_), "{:.3f}", v); break;
      case TraceLayout::Format::deg: fmt::format_to(std::back_inserter(row_), "{:.4f}", v); break;
      case TraceLayout::Format::whole: fmt::format_to(std::back_inserter(row_), "{:.0f}", v); break;
    }
  });
  for (std::size_t c = 0; c < path_.size(); ++c) {
    const PathDerivatives& d = path_[c];
    if (extra_.path_v) fmt::format_to(std::back_inserter(row_), ",{:.6f}", out.channels[c].path_velocity_mm_s);
    if (extra_.path_a) fmt::format_to(std::back_inserter(row_), ",{:.3f}", d.a_mm_s2());
    if (extra_.path_j) fmt::format_to(std::back_inserter(row_), ",{:.1f}", d.j_mm_s3());
  }
  row_ += '\n';
  file_.write(row_);
}

}  // namespace nck::app
