#include "output_writers.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "machine_names.hpp"
#include "nck/core/utf8.hpp"
#include "nck/distctrl/controller.hpp"
#include "nck/spindle/spindle_status.hpp"

namespace nck::app {

// ordered: "t", "ch", "ev" first in every event line
using json = nlohmann::ordered_json;

nlohmann::ordered_json RunNames::spindle(std::int8_t index) const {
  if (index < 0 || !run || static_cast<std::size_t>(index) >= run->kernel().spindle_count()) return nullptr;
  return run->kernel().spindle_name(static_cast<std::size_t>(index));
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

std::string RunNames::text(const kernel::Event& e) const {
  if (e.message_index != kernel::kNoMessage && run) return to_utf8(run->message(e.message_index));
  const ErrorInfo* info = find_error(e.id);
  return info ? fmt::format("{}: {}", info->text, info->remedy) : std::string();
}

std::string RunNames::file(std::size_t ch, std::uint16_t id) const {
  const nc::Decoder* d = run && ch < run->channel_count() ? run->prep(ch).decoder() : nullptr;
  return d ? to_utf8(d->file_name(id)) : std::string();
}

std::string sync_name(std::uint32_t bits) {
  namespace s = config::sync;
  static constexpr std::pair<std::uint32_t, const char*> kNames[] = {
      {s::MOS, "MOS"},         {s::MVS_SVS, "MVS_SVS"}, {s::MVS_SNS, "MVS_SNS"},
      {s::MNS_SNS, "MNS_SNS"}, {s::MNE_SNS, "MNE_SNS"}, {s::MVS_SLM, "MVS_SLM"},
      {s::MVS_SLP, "MVS_SLP"}, {s::PLC_INFO, "PLC_INFO"}};
  std::string out;
  for (auto [bit, name] : kNames) {
    if (!(bits & bit)) continue;
    if (!out.empty()) out += '|';
    out += name;
  }
  return out.empty() ? "NO_SYNCH" : out;
}

namespace {

const char* kind_name(kernel::EventKind k) {
  using K = kernel::EventKind;
  switch (k) {
    case K::block: return "block";
    case K::plc_out: return "plc_out";
    case K::plc_ack: return "plc_ack";
    case K::wait: return "wait";
    case K::wait_end: return "wait_end";
    case K::spindle: return "spindle";
    case K::speed_reached: return "speed_reached";
    case K::gear: return "gear";
    case K::link: return "link";
    case K::offset: return "offset";
    case K::stop: return "stop";
    case K::warning: return "warning";
    case K::error: return "error";
    case K::end: return "end";
    case K::dist_ctrl: return "dist_ctrl";
    case K::trc: return "trc";
    case K::state: return "state";
  }
  return "unknown";
}

}  // namespace

std::optional<kernel::EventKind> event_kind_from(std::string_view name) {
  for (int k = 0; k <= static_cast<int>(kernel::EventKind::state); ++k)
    if (name == kind_name(static_cast<kernel::EventKind>(k))) return static_cast<kernel::EventKind>(k);
  return std::nullopt;
}

const char* wait_reason_name(kernel::WaitReason r) {
  using W = kernel::WaitReason;
  switch (r) {
    case W::plc_ack: return "plc_ack";
    case W::speed_reached: return "speed_reached";
    case W::in_position: return "in_position";
    case W::standstill: return "standstill";
    case W::homing: return "homing";
    case W::gear_change: return "gear_change";
    case W::expl_syn: return "expl_syn";
    case W::dwell: return "dwell";
    case W::feedhold: return "feedhold";
    case W::coupling: return "coupling";
  }
  return "plc_ack";
}

const char* link_reason_name(kernel::LinkReason r) {
  using R = kernel::LinkReason;
  switch (r) {
    case R::program: return "program";
    case R::abort: return "abort";
    case R::program_end: return "program_end";
    case R::reset: return "reset";
  }
  return "program";
}

const char* end_name(kernel::EndReason r) {
  using R = kernel::EndReason;
  switch (r) {
    case R::m30: return "M30";
    case R::m2: return "M2";
    case R::error: return "error";
    case R::reset: return "reset";
    case R::max_time: return "max_time";
    case R::max_wall: return "max_wall";
    case R::interrupted: return "interrupted";
    case R::hold: return "hold";
    case R::stop_at: return "stop_at";
    case R::max_trace: return "max_trace";
  }
  return "error";
}

namespace {

std::string function_name(plc::TechKind fn, std::int32_t number) {
  using F = plc::TechKind;
  switch (fn) {
    case F::m: return fmt::format("M{}", number);
    case F::h: return fmt::format("H{}", number);
    case F::t: return fmt::format("T{}", number);
    case F::s: return "S";
    case F::none: break;
  }
  return "";
}

json base_event(const kernel::Event& e) {
  json j;
  j["t"] = e.t_s;
  if (e.channel > 0) j["ch"] = e.channel;
  j["ev"] = kind_name(e.kind);
  return j;
}

}  // namespace

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
  s.append(num, std::to_chars(num, num + sizeof num, e.line).ptr);
  s += ",\"n\":";
  if (e.has_n) s.append(num, std::to_chars(num, num + sizeof num, e.n).ptr);
  else s += "null";
  s += ",\"file\":";
  s += quoted_file(e.channel > 0 ? e.channel - 1u : 0u, e.file_id, names);
  s += '}';
  return s;
}

nlohmann::ordered_json EventWriter::object(const kernel::Event& e, const RunNames& names) {
  json j = base_event(e);
  const std::size_t ch = e.channel > 0 ? e.channel - 1u : 0u;
  using K = kernel::EventKind;
  switch (e.kind) {
    case K::block:
    case K::stop:
      j["line"] = e.line;
      j["n"] = e.has_n ? json(e.n) : json(nullptr);
      j["file"] = names.file(ch, e.file_id);
      break;
    case K::plc_out:
    case K::plc_ack:
      j["fn"] = function_name(e.fn, e.fn_number);
      j["spindle"] = names.spindle(e.spindle);
      j["value"] = e.fn == plc::TechKind::s ? json(e.value) : json(nullptr);
      if (e.kind == K::plc_out) j["sync"] = sync_name(e.sync);
      break;
    case K::wait:
    case K::wait_end:
      j["reason"] = wait_reason_name(e.wait_reason);
      j["spindle"] = names.spindle(e.spindle);
      j["fn"] = function_name(e.fn, e.fn_number);
      j["line"] = e.line;
      break;
    case K::spindle:
      j["spindle"] = names.spindle(e.spindle);
      j["mode"] = spindle::mode_name(e.spindle_mode);
      j["rpm"] = e.value;
      j["gear"] = e.gear;
      break;
    case K::speed_reached:
      j["spindle"] = names.spindle(e.spindle);
      j["rpm"] = e.value;
      break;
    case K::gear:
      j["spindle"] = names.spindle(e.spindle);
      j["stage"] = e.gear;
      j["fn"] = function_name(e.fn, e.fn_number);
      break;
    case K::warning:
    case K::error:
      j["id"] = number(e.id);
      j["line"] = e.line;
      j["file"] = names.file(ch, e.file_id);
      j["msg"] = names.text(e);
      if (e.spindle >= 0) j["spindle"] = names.spindle(e.spindle);
      break;
    case K::end:
      j["reason"] = end_name(e.end_reason);
      break;
    case K::state:
      j["from"] = kernel::state_name(e.state_from);
      j["to"] = kernel::state_name(e.state_to);
      j["reason"] = kernel::state_reason_name(e.state_reason);
      j["line"] = e.line;
      j["n"] = e.has_n ? json(e.n) : json(nullptr);
      j["file"] = names.file(ch, e.file_id);
      break;
    case K::link: {
      const prep::LinkPayload& p = names.run->link(e.message_index);
      j["group"] = e.link_group;
      json pairs = json::array();
      for (const auto& [slave, master] : p.pairs) pairs.push_back(json::array({slave, master}));
      j["pairs"] = pairs;
      j["on"] = e.link_on;
      j["reason"] = link_reason_name(e.link_reason);
      j["line"] = e.line;
      break;
    }
    case K::dist_ctrl:
      j["state"] = distctrl::state_name(e.dist_state);
      j["line"] = e.line;
      break;
    case K::trc: {
      j["state"] = e.trc_mode == nc::RadiusComp::g41   ? "G41"
                   : e.trc_mode == nc::RadiusComp::g42 ? "G42"
                                                       : "G40";
      j["d"] = e.trc_d;
      j["radius_mm"] = e.trc_radius_mm;
      j["line"] = e.line;
      j["file"] = names.file(ch, e.file_id);
      break;
    }
    case K::offset: {
      const prep::OffsetPayload& p = names.run->offset(e.message_index);
      j["kind"] = p.kind;
      json values = json::object();
      for (const auto& [axis, v] : p.values) values[axis] = v;
      j["values"] = values;
      j["line"] = e.line;
      break;
    }
    default:
      break;
  }
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
  for (const PathDerivatives& d : path_) {
    if (extra_.path_a) fmt::format_to(std::back_inserter(row_), ",{:.3f}", d.a_mm_s2());
    if (extra_.path_j) fmt::format_to(std::back_inserter(row_), ",{:.1f}", d.j_mm_s3());
  }
  row_ += '\n';
  file_.write(row_);
}

}  // namespace nck::app
