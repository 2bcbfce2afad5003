#include "nck/serve/offset_book.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

#include "nck/config/list_reader.hpp"
#include "nck/config/parameter_registry.hpp"
#include "nck/core/path_within.hpp"
#include "nck/core/shown_number.hpp"

namespace nck::app::serve {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

Diagnostic refusal(ErrorId id, std::string message) { return make_diagnostic(id, SourceLoc{}, std::move(message)); }

// A value as the list writes it (0.1 um, 0.001 deg/s ...), checked against
// the key's registry entry as the loader checks it; the reason otherwise.
std::expected<std::string, Diagnostic> list_value(config::ListKind list, std::string_view pattern, std::string_view key,
                                                  double value) {
  const config::ParamInfo* p = config::find_parameter(list, pattern);
  if (!p) return std::unexpected(refusal(ErrorId::OffsetNotFound, fmt::format("no list key {}", key)));
  const double in_list = value / p->scale;
  const bool integral = p->type == config::ParamType::integer;
  const double written = integral ? std::round(in_list) : in_list;
  if (!std::isfinite(value) || written < p->min || written > p->max)
    return std::unexpected(refusal(
        ErrorId::OffsetOutOfRange,
        fmt::format("{} {} {} is outside {} .. {} {} ({} .. {} {}, {})", key, value, p->internal_unit, p->min * p->scale,
                    p->max * p->scale, p->internal_unit, p->min, p->max, p->list_unit, p->id)));
  // A whole number as an integer (a real key's 4800000, not 4.8e+06).
  if (integral || (written == std::floor(written) && std::abs(written) < 1e15))
    return fmt::format("{}", static_cast<long long>(written));
  return fmt::format("{}", written);
}

// The channels whose list of this kind is `file` (two channels may share one).
template <class F>
void for_each_sharing(config::Machine& m, fs::path config::ChannelConfig::*list, std::size_t ch, F&& f) {
  for (std::size_t i = 0; i < m.channels.size() && i < m.channel_data.size(); ++i)
    if (i == ch || (!(m.channels[ch].*list).empty() && m.channels[i].*list == m.channels[ch].*list)) f(m.channel_data[i]);
}

json axis_values(const config::ChannelConfig& c, const AxisArray& v) {
  json o = json::object();
  for (std::size_t j = 0; j < c.axes.size() && j < v.size(); ++j) o[c.axes[j].name] = shown(v[j]);
  return o;
}

std::string file_name(const fs::path& p) { return p.empty() ? std::string() : p.filename().string(); }

// A tool of an inch list (wz[n].mass_einheit 1): its values are not mm.
bool inch_tool(const fs::path& file, std::size_t tool) {
  Diagnostics ignored;
  const auto text = config::read_list_file(file, file.string(), ignored);
  if (!text) return false;
  const std::string key = fmt::format("wz[{}].mass_einheit", tool);
  for (const config::ListLine& l : text->lines)
    if (l.key == key) return config::parse_number(l.value).value_or(0) == 1;
  return false;
}

}  // namespace

std::optional<std::size_t> zero_group_of(std::string_view offset) {
  static constexpr std::string_view kNames[] = {"G54", "G55", "G56", "G57", "G58", "G59"};
  for (std::size_t i = 0; i < 6; ++i)
    if (offset == kNames[i]) return i + 1;
  return std::nullopt;
}

std::optional<std::size_t> channel_axis_of(const config::ChannelConfig& c, std::string_view axis) {
  for (std::size_t j = 0; j < c.axes.size(); ++j)
    if (c.axes[j].name == axis) return j;
  return std::nullopt;
}

OffsetBook::OffsetBook(const config::Machine& m) : folder_(m.folder) { reloaded(m); }

void OffsetBook::reloaded(const config::Machine& m) {
  loaded_.clear();
  edits_.clear();
  for (const config::ChannelConfig& c : m.channels)
    for (const fs::path* f : {&c.zero_list, &c.clamp_list, &c.tool_list})
      if (!f->empty()) fingerprint(*f);
}

void OffsetBook::fingerprint(const fs::path& file) { loaded_[file] = fingerprint_file(file); }

void OffsetBook::remember(const fs::path& file, std::string key, std::string list_value) {
  edits_[file][std::move(key)] = std::move(list_value);
}

json OffsetBook::tables_json(const config::Machine& m) const {
  json channels = json::array();
  for (std::size_t ch = 0; ch < m.channels.size() && ch < m.channel_data.size(); ++ch) {
    const config::ChannelConfig& c = m.channels[ch];
    const config::ChannelData& d = m.channel_data[ch];
    json axes = json::array(), zero = json::array(), clamp = json::array(), tools = json::array();
    for (const auto& a : c.axes) axes.push_back(a.name);
    for (std::size_t g = 1; g <= 6 && g < d.zero.versch.size(); ++g)
      zero.push_back({{"offset", fmt::format("G{}", 53 + g)}, {"group", g}, {"values_mm", axis_values(c, d.zero.versch[g])}});
    for (std::size_t g = 0; g < d.clamp.versatz.size(); ++g)
      clamp.push_back({{"group", g}, {"values_mm", axis_values(c, d.clamp.versatz[g])}});
    for (std::size_t n = 1; n < d.tools.size(); ++n) {
      const config::ToolRecord& t = d.tools[n];
      if (!t.given) continue;
      // The speeds at 1e-6 rpm: the list's unit, 0.001°/s, is 1/6000 rpm,
      // finer than a position's step (a vb_max of 1 would read 0.0002).
      tools.push_back({{"tool", n}, {"length_mm", shown(t.length_mm)}, {"radius_mm", shown(t.radius_mm)},
                       {"spindle", t.log_ax_nr_spdl}, {"vb_min_rpm", written(t.vb_min_rpm)},
                       {"vb_max_rpm", written(t.vb_max_rpm)}, {"a_max_deg_s2", shown(t.a_max_deg_s2)}});
    }
    channels.push_back({{"channel", ch + 1}, {"axes", std::move(axes)}, {"zero", std::move(zero)},
                        {"clamp", std::move(clamp)}, {"tools", std::move(tools)},
                        {"files", {{"zero", file_name(c.zero_list)}, {"clamp", file_name(c.clamp_list)},
                                   {"tools", file_name(c.tool_list)}}}});
  }
  return {{"channels", std::move(channels)}, {"unsaved", unsaved()}};
}

std::optional<Diagnostic> OffsetBook::set_zero(config::Machine& m, std::size_t ch, std::string_view offset,
                                               std::string_view axis, double value_mm) {
  const auto g = zero_group_of(offset);
  if (!g) return refusal(ErrorId::OffsetNotFound, fmt::format("'{}' is no zero offset: G54 .. G59", offset.substr(0, 40)));
  const auto j = channel_axis_of(m.channels[ch], axis);
  if (!j) return refusal(ErrorId::OffsetNotFound, fmt::format("channel {} has no axis '{}'", ch + 1, axis.substr(0, 40)));
  const std::string key = fmt::format("np_grp[{}].achse[{}].versch", *g, *j);
  auto v = list_value(config::ListKind::zero, "np_grp[].achse[].versch", key, value_mm);
  if (!v) return v.error();
  for_each_sharing(m, &config::ChannelConfig::zero_list, ch, [&](config::ChannelData& d) {
    if (d.zero.versch.size() <= *g) d.zero.versch.resize(*g + 1);
    d.zero.versch[*g][*j] = value_mm;
  });
  remember(m.channels[ch].zero_list, key, std::move(*v));
  return std::nullopt;
}

std::optional<Diagnostic> OffsetBook::set_clamp(config::Machine& m, std::size_t ch, std::size_t group,
                                                std::string_view axis, double value_mm) {
  if (group >= m.channel_data[ch].clamp.versatz.size())
    return refusal(ErrorId::OffsetNotFound, fmt::format("channel {} has no clamp-offset group {}", ch + 1, group));
  const auto j = channel_axis_of(m.channels[ch], axis);
  if (!j) return refusal(ErrorId::OffsetNotFound, fmt::format("channel {} has no axis '{}'", ch + 1, axis.substr(0, 40)));
  const std::string key = fmt::format("pzv_grp[{}].achse[{}].versatz", group, *j);
  auto v = list_value(config::ListKind::clamp, "pzv_grp[].achse[].versatz", key, value_mm);
  if (!v) return v.error();
  for_each_sharing(m, &config::ChannelConfig::clamp_list, ch,
                   [&](config::ChannelData& d) { d.clamp.versatz[group][*j] = value_mm; });
  remember(m.channels[ch].clamp_list, key, std::move(*v));
  return std::nullopt;
}

std::optional<Diagnostic> OffsetBook::set_tool(config::Machine& m, std::size_t ch, std::size_t tool, const ToolEdit& e) {
  const auto& tools = m.channel_data[ch].tools;
  if (tool == 0 || tool >= tools.size() || !tools[tool].given)
    return refusal(ErrorId::OffsetNotFound, fmt::format("the tool list of channel {} has no tool {}", ch + 1, tool));
  const fs::path& file = m.channels[ch].tool_list;
  if (inch_tool(file, tool))
    return refusal(ErrorId::OffsetListNotSaved,
                   fmt::format("tool {} is given in inch (wz[{}].mass_einheit 1): edit it in {}", tool, tool, file_name(file)));
  config::ToolRecord t = tools[tool];
  std::vector<std::pair<std::string, std::string>> values;
  const auto field = [&](const std::optional<double>& in, double& out, std::string_view name, std::string_view pattern) {
    if (!in) return std::optional<Diagnostic>{};
    const std::string key = fmt::format("wz[{}].{}", tool, name);
    auto v = list_value(config::ListKind::tool, pattern, key, *in);
    if (!v) return std::optional<Diagnostic>{v.error()};
    out = *in;
    values.emplace_back(key, std::move(*v));
    return std::optional<Diagnostic>{};
  };
  for (auto d : {field(e.length_mm, t.length_mm, "laenge", "wz[].laenge"),
                 field(e.radius_mm, t.radius_mm, "radius", "wz[].radius"),
                 field(e.vb_min_rpm, t.vb_min_rpm, "vb_min", "wz[].vb_min"),
                 field(e.vb_max_rpm, t.vb_max_rpm, "vb_max", "wz[].vb_max"),
                 field(e.a_max_deg_s2, t.a_max_deg_s2, "a_max", "wz[].a_max")})
    if (d) return d;
  if (t.vb_min_rpm > t.vb_max_rpm)  // the loader's cross-check of the pair
    return refusal(ErrorId::OffsetOutOfRange, fmt::format("tool {}: vb_min {} rpm must not exceed vb_max {} rpm", tool,
                                                          t.vb_min_rpm, t.vb_max_rpm));
  for_each_sharing(m, &config::ChannelConfig::tool_list, ch, [&](config::ChannelData& d) {
    if (tool < d.tools.size()) d.tools[tool] = t;
  });
  for (auto& [key, v] : values) remember(file, key, std::move(v));
  return std::nullopt;
}

std::expected<std::vector<std::string>, Diagnostic> OffsetBook::save() {
  std::error_code ec;
  const fs::path folder = fs::canonical(folder_, ec);
  // Every file is checked before the first is written: a refusal writes nothing.
  for (const auto& [file, values] : edits_) {
    const fs::path real = file.empty() ? fs::path() : fs::weakly_canonical(file, ec);
    if (file.empty() || folder.empty() || !path_within(folder, real))
      return std::unexpected(refusal(ErrorId::OffsetListNotSaved,
                                     file.empty() ? std::string("the channel names no list file for these edits")
                                                  : fmt::format("{} lies outside the machine folder {}", file.string(),
                                                                folder_.string())));
    const auto it = loaded_.find(file);
    const auto now = fingerprint_file(file);
    if (it == loaded_.end() || !now || it->second != now)
      return std::unexpected(
          refusal(ErrorId::OffsetListChanged, fmt::format("{} changed on disk since it was loaded: reload the lists", file_name(file))));
  }
  std::vector<std::string> written;
  for (auto it = edits_.begin(); it != edits_.end();) {
    const auto& [file, values] = *it;
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const std::string updated = rewrite_list(text.str(), values);
    if (auto why = replace_file_with_backup(file, updated))
      return std::unexpected(refusal(ErrorId::OffsetListNotSaved, *why + (written.empty() ? "" : " (the files before it were saved)")));
    loaded_[file] = fingerprint_of(updated);
    written.push_back(file_name(file));
    it = edits_.erase(it);
  }
  return written;
}

}  // namespace nck::app::serve
