// POST /api/v1/home {"channel":1,"axes":["X","Z"]} (token required like
// every request; "axes" left out: every path axis of the channel): homes
// the axes with G74, all with order 1 (together), through the same path as
// MDI, so the kernel marks them homed at their home position
// (P-AXIS-00277, docs/decisions.md "Homing and P-AXIS-00277"). Checked
// whole before anything is sent: an unknown axis (940341) or a channel in
// automatic mode (940340: a program runs, holds, waits or searches) is
// answered with its ID and nothing starts.
#include <algorithm>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "nck/serve/serve_api.hpp"

namespace nck::app::serve {

namespace {

constexpr std::size_t kMaxHomeBytes = 4096;

}  // namespace

// The G74 block that homes `axes` of channel cfg (all when empty), or the
// axis that is none of the channel's.
std::expected<std::string, std::string> homing_block(const config::ChannelConfig& cfg,
                                                     const std::vector<std::string>& axes) {
  std::string text = "G74";
  for (const config::ChannelAxis& a : cfg.axes)
    if (axes.empty() || std::ranges::find(axes, a.name) != axes.end()) text += fmt::format(" {}1", a.name);
  for (const std::string& name : axes)
    if (std::ranges::none_of(cfg.axes, [&](const config::ChannelAxis& a) { return a.name == name; }))
      return std::unexpected(name);
  return text;
}

HttpReply ServeApi::home(std::string_view body) {
  if (body.size() > kMaxHomeBytes)
    return error_reply(413, ErrorId::ApiTooLarge, fmt::format("a homing request is at most {} bytes", kMaxHomeBytes));
  const nlohmann::json j = nlohmann::json::parse(body, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return error_reply(400, ErrorId::ApiMalformedJson, "the body is not one JSON object");
  for (const auto& [key, value] : j.items())
    if (key != "channel" && key != "axes")
      return error_reply(400, ErrorId::ApiUnknownField, fmt::format("'{}' is no field of /api/v1/home", key.substr(0, 40)));
  const auto c = j.find("channel");
  std::size_t channel = 1;
  if (c != j.end()) {
    if (!c->is_number_unsigned() || c->get<std::size_t>() < 1 || c->get<std::size_t>() > machine_.channels.size())
      return error_reply(400, ErrorId::ApiBadValue, fmt::format("'channel' is 1..{}", machine_.channels.size()));
    channel = c->get<std::size_t>();
  }
  std::vector<std::string> axes;
  if (const auto a = j.find("axes"); a != j.end()) {
    if (!a->is_array() || a->empty() || a->size() > kMaxAxes)
      return error_reply(400, ErrorId::HomeUnknownAxis, "'axes' is a list of the channel's path axis names");
    for (const auto& name : *a) {
      if (!name.is_string()) return error_reply(400, ErrorId::HomeUnknownAxis, "'axes' holds axis names (strings)");
      axes.push_back(name.get<std::string>());
    }
  }
  const std::size_t ch = channel - 1;
  const auto block = homing_block(machine_.channels[ch], axes);
  if (!block)
    return error_reply(400, ErrorId::HomeUnknownAxis,
                       fmt::format("'{}' is no path axis of channel {}", block.error().substr(0, 40), channel));
  if (!channel_free(last_.channels[ch].program_state))
    return error_reply(409, ErrorId::HomeRefusedAutomatic,
                       fmt::format("channel {} is {}: homing waits for the program end or a reset", channel,
                                   kernel::state_name(last_.channels[ch].program_state)));
  if (auto no = refused_by_machine(sim::ActionKind::mdi, ch)) return *no;
  HttpReply r = mdi(ch, *block, false);
  if (r.status == 200) r.body = nlohmann::json{{"ok", true}, {"mdi", *block}}.dump();
  return r;
}

}  // namespace nck::app::serve
