// nck serve's offsets and tools routes (issue 48 item 8; docs/api.md):
// the zero offsets, clamp offsets and tool table of the server's machine
// copy, edited and touched off from the HMI, written back to the list files
// on an explicit save. An edit takes effect at the next run the server
// makes (a load, a cycle start, and at once when every channel is idle);
// a zero offset also at its next selection in a running program
// (docs/decisions.md, "Offsets and tools from the HMI").
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "nck/config/load.hpp"
#include "nck/core/shown_number.hpp"
#include "nck/output/diagnostic_json.hpp"
#include "nck/run/state_document.hpp"
#include "nck/serve/serve_api.hpp"

namespace nck::app::serve {
namespace {

using json = nlohmann::ordered_json;

inline constexpr std::size_t kMaxOffsetBodyBytes = 4096;

// The body as one JSON object whose fields are all in `allowed`, or the refusal.
std::expected<json, HttpReply> body_object(std::string_view body, std::initializer_list<std::string_view> allowed) {
  if (body.size() > kMaxOffsetBodyBytes)
    return std::unexpected(error_reply(413, ErrorId::ApiTooLarge, fmt::format("an offsets request is at most {} bytes", kMaxOffsetBodyBytes)));
  json j = json::parse(body.empty() ? std::string_view("{}") : body, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return std::unexpected(error_reply(400, ErrorId::ApiMalformedJson, "the body is not one JSON object"));
  for (const auto& [key, value] : j.items())
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      return std::unexpected(error_reply(400, ErrorId::ApiUnknownField, fmt::format("no field '{}' here (docs/api.md)", key.substr(0, 40))));
  return j;
}

std::optional<double> number(const json& j, std::string_view key) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number()) return std::nullopt;
  return it->get<double>();
}
std::optional<std::string> text(const json& j, std::string_view key) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_string()) return std::nullopt;
  return it->get<std::string>();
}
HttpReply missing(std::string_view what) {
  return error_reply(400, ErrorId::ApiBadValue, fmt::format("'{}' is missing or of the wrong type (docs/api.md)", what));
}

// The #ACS and #CS the running program set, as its offset events give
// them (X Y Z shifts and angle1..3; "2.X" ... for the second of a chain).
// Programmed, not listed: shown, not edited.
json coordinate_systems_json(const BlockContext& c, const sim::DryRun& run) {
  json systems = json::array();
  for (const auto& index : {c.acs_offset, c.cs_offset}) {
    if (!index) continue;
    const prep::OffsetPayload& o = run.offset(*index);
    json values = json::object();
    for (const auto& [name, v] : o.values) values[name] = shown(v);
    systems.push_back({{"kind", o.kind}, {"values", std::move(values)}});
  }
  return systems;
}

}  // namespace

std::optional<HttpReply> ServeApi::offsets_route(const HttpRequest& r) {
  const std::string_view path = r.target.substr(0, r.target.find('?'));
  if (!path.starts_with("/api/v1/offsets") && !path.starts_with("/api/v1/tools/")) return std::nullopt;
  if (r.method == "GET" && path == "/api/v1/offsets") return offsets_page();
  if (r.method != "POST") return std::nullopt;
  if (path == "/api/v1/offsets/save") {
    if (auto b = body_object(r.body, {}); !b) return b.error();
    auto written = offsets_.save();
    if (!written) return error_reply(written.error().id == ErrorId::OffsetListChanged ? 409 : 400, written.error());
    return HttpReply{200, "application/json", dump_json(json{{"ok", true}, {"written", *written}}), {}};
  }
  if (path == "/api/v1/offsets/reload") {
    if (auto b = body_object(r.body, {}); !b) return b.error();
    return reload_lists();
  }
  return edit_offset(path, r.body);
}

HttpReply ServeApi::offsets_page() const {
  json j = offsets_.tables_json(machine_);
  for (auto& c : j["channels"]) {
    const std::size_t ch = c["channel"].get<std::size_t>() - 1;
    const auto& modal = frames_[ch].modal;
    const int zero = modal ? modal->zero_offset : 0;
    c["active_zero"] = zero >= 1 && zero <= 6 ? json(fmt::format("G{}", 53 + zero)) : zero == 0 ? json("G53") : json(zero);
    c["active_tool"] = modal ? modal->d : 0;
    c["busy"] = ch < last_.channel_count && !channel_free(last_.channels[ch].program_state);
    c["coordinate_systems"] = coordinate_systems_json(frames_[ch], *serving_);
  }
  return HttpReply{200, "application/json", dump_json(j), {}};
}

HttpReply ServeApi::edit_offset(std::string_view path, std::string_view body) {
  const bool tool = path.starts_with("/api/v1/tools/");
  const bool zero = path == "/api/v1/offsets/zero", clamp = path == "/api/v1/offsets/clamp",
             touch = path == "/api/v1/offsets/touch_off";
  if (!tool && !zero && !clamp && !touch) return error_reply(404, ErrorId::ApiNotFound, fmt::format("no POST {} (docs/api.md)", path.substr(0, 80)));
  const auto b = tool    ? body_object(body, {"channel", "length_mm", "radius_mm", "vb_min_rpm", "vb_max_rpm", "a_max_deg_s2"})
                 : clamp ? body_object(body, {"channel", "group", "axis", "value_mm"})
                 : touch ? body_object(body, {"channel", "offset", "axis", "reads_mm"})
                         : body_object(body, {"channel", "offset", "axis", "value_mm"});
  if (!b) return b.error();
  const json& j = *b;
  const double channel = number(j, "channel").value_or(1);
  if (channel != std::floor(channel) || channel < 1 || channel > static_cast<double>(machine_.channels.size()))
    return error_reply(400, ErrorId::ApiBadValue, "'channel' is no channel of the machine");
  const auto ch = static_cast<std::size_t>(channel) - 1;
  if (tool) {
    const std::string_view digits = path.substr(std::string_view("/api/v1/tools/").size());
    char* end = nullptr;
    const std::string n_text(digits.substr(0, 12));
    const unsigned long n = std::strtoul(n_text.c_str(), &end, 10);
    if (n_text.empty() || *end != '\0') return error_reply(404, ErrorId::ApiNotFound, "POST /api/v1/tools/{n}: n is a tool number");
    ToolEdit e{number(j, "length_mm"), number(j, "radius_mm"), number(j, "vb_min_rpm"), number(j, "vb_max_rpm"), number(j, "a_max_deg_s2")};
    for (std::size_t c = 0; c < last_.channel_count; ++c)  // the tool a running program has selected
      if (!channel_free(last_.channels[c].program_state) && frames_[c].modal && frames_[c].modal->d == static_cast<std::int64_t>(n))
        return error_reply(409, make_diagnostic(ErrorId::OffsetToolInUse, SourceLoc{},
                                                fmt::format("channel {} runs with tool D{}: the edit is refused (not deferred)", c + 1, n)));
    return edited(offsets_.set_tool(machine_, ch, n, e));
  }
  const auto axis = text(j, "axis");
  if (!axis) return missing("axis");
  if (clamp) {
    const auto group = number(j, "group"), value = number(j, "value_mm");
    if (!group || *group < 0 || *group != std::floor(*group) || *group > 1e6) return missing("group");
    if (!value) return missing("value_mm");
    return edited(offsets_.set_clamp(machine_, ch, static_cast<std::size_t>(*group), *axis, *value));
  }
  const auto offset = text(j, "offset");
  if (!offset) return missing("offset");
  if (touch) {
    const auto reads = number(j, "reads_mm");
    return touch_off(ch, *offset, *axis, reads.value_or(0));
  }
  const auto value = number(j, "value_mm");
  if (!value) return missing("value_mm");
  return edited(offsets_.set_zero(machine_, ch, *offset, *axis, *value));
}

// Touch-off: the offset's value that makes the axis read `reads_mm` once the
// offset is selected. The state's PCS is MCS minus the frame's shift (no
// rotation), the shift being the active zero offset plus every other shift
// (clamp, tool length, G92 ...): value = MCS - reads - other shifts
// = active offset (the run's) + PCS - reads.
HttpReply ServeApi::touch_off(std::size_t ch, const std::string& offset, const std::string& axis, double reads_mm) {
  const auto refused = [&](std::string why) {
    return error_reply(409, make_diagnostic(ErrorId::OffsetTouchOffRefused, SourceLoc{}, std::move(why)), ch + 1);
  };
  if (!std::isfinite(reads_mm)) return missing("reads_mm");
  if (ch < last_.channel_count && !channel_free(last_.channels[ch].program_state))
    return refused(fmt::format("channel {} runs a program: touch off at rest", ch + 1));
  const BlockContext& context = frames_[ch];
  if (!context.frame.pure_translation) return refused("a rotation or mirroring is active: the PCS is not a shifted MCS");
  const auto j = channel_axis_of(machine_.channels[ch], axis);
  if (!j || !zero_group_of(offset)) return edited(offsets_.set_zero(machine_, ch, offset, axis, 0));  // its refusal
  const auto places = channel_places(last_, machine_, frames_);
  const int active = context.modal ? context.modal->zero_offset : 0;
  double active_mm = 0;
  const config::Machine& ran = serving_->config();
  if (active > 0 && ch < ran.channel_data.size() && static_cast<std::size_t>(active) < ran.channel_data[ch].zero.versch.size())
    active_mm = ran.channel_data[ch].zero.versch[static_cast<std::size_t>(active)][*j];
  const double value_mm = std::round((active_mm + places[ch].pcs[*j] - reads_mm) * 1e4) / 1e4;  // the list's 0.1 um
  if (auto d = offsets_.set_zero(machine_, ch, offset, axis, value_mm)) return edited(std::move(d));
  HttpReply r = edited(std::nullopt);
  json answer = json::parse(r.body);
  answer["value_mm"] = value_mm;
  r.body = dump_json(answer);
  return r;
}

// After an edit: the staged run is made again from the edited machine; an
// idle kernel gets a fresh run without programs, so that an MDI G54 selects
// the new value (as a program start would); a running program's next
// selection of a zero offset takes it.
HttpReply ServeApi::edited(std::optional<Diagnostic> refusal) {
  if (refusal) {
    const bool missing_thing = refusal->id == ErrorId::OffsetNotFound;
    return error_reply(missing_thing ? 404 : 422, *refusal);
  }
  for (std::string& p : previews_) p.clear();  // a preview shows the offsets
  if (staged_) {
    auto run = make_run(staged_search_, staged_search_channel_);
    if (run) staged_ = std::move(*run);
  }
  if (!busy_channel()) {
    if (auto run = make_run(std::nullopt, 0, false)) (void)kernel_.load(std::move(*run));
  } else if (sim::DryRun* running = kernel_.current()) {  // its next G54..G59 selects the new values
    for (std::size_t ch = 0; ch < machine_.channel_data.size(); ++ch)
      running->offer_zero_offsets(ch, machine_.channel_data[ch].zero);
  }
  json j = offsets_.tables_json(machine_);
  return HttpReply{200, "application/json", dump_json(json{{"ok", true}, {"unsaved", j["unsaved"]}}), {}};
}

// The lists read again from the machine folder: unsaved edits go.
HttpReply ServeApi::reload_lists() {
  config::LoadResult loaded = config::load_machine(machine_.folder, {});
  if (!loaded.ok()) return error_reply(422, loaded.diagnostics.items().front());
  if (loaded.machine->channels.size() != machine_.channels.size())
    return error_reply(409, ErrorId::OffsetListChanged, "the machine's channels changed on disk: restart nck serve");
  machine_.channel_data = loaded.machine->channel_data;
  offsets_.reloaded(machine_);
  return edited(std::nullopt);
}

}  // namespace nck::app::serve
