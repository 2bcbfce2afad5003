#include "nck/serve/api_message.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <memory>
#include <unordered_set>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "nck/serve/speed_range.hpp"

namespace nck::app::serve {
namespace {

using json = nlohmann::json;

// Checks one message against its command's schema; the first problem wins.
class Reader {
 public:
  Reader(const json& j, Diagnostics& diags) : j_(j), diags_(diags) {}

  bool fail(ErrorId id, std::string msg) {
    if (ok_) diags_.add(id, SourceLoc{}, std::move(msg));
    ok_ = false;
    return false;
  }
  bool ok() const { return ok_; }

  // Every field is one of `allowed` (besides "command" and "channel").
  void only(std::initializer_list<std::string_view> allowed) {
    for (const auto& [key, _] : j_.items()) {
      if (key == "command" || key == "channel") continue;
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
        fail(ErrorId::ApiUnknownField, fmt::format("'{}' is no field of '{}'", shown(key), command()));
    }
  }
  std::string command() const { return j_.value("command", std::string()); }

  bool boolean(const char* key, bool required = true) {
    const json* v = required ? field(key) : optional_field(key);
    if (!v) return false;
    if (!v->is_boolean()) return fail(ErrorId::ApiBadValue, fmt::format("'{}' must be true or false", key));
    return v->get<bool>();
  }
  double number(const char* key, double lowest, double highest, bool required = true, double otherwise = 0) {
    const json* v = required ? field(key) : optional_field(key);
    if (!v) return otherwise;
    if (!v->is_number()) return fail(ErrorId::ApiBadValue, fmt::format("'{}' must be a number", key)), otherwise;
    const double x = v->get<double>();
    if (!(x >= lowest && x <= highest))
      return fail(ErrorId::ApiBadValue, fmt::format("'{}' must lie in {}..{}", key, lowest, highest)), otherwise;
    return x;
  }
  // A speed: "max" or 0 (as fast as possible), or kMinSpeed..kMaxSpeed.
  double speed(const char* key) {
    const json* v = field(key);
    if (v && v->is_string() && v->get<std::string>() == "max") return kSpeedMax;
    const double x = number(key, kSpeedMax, kMaxSpeed, true, 1);
    if (ok_ && !speed_allowed(x))
      fail(ErrorId::ApiBadValue, fmt::format("'{}' must be 0 or \"max\" (as fast as possible) or lie in {}..{}", key,
                                             kMinSpeed, kMaxSpeed));
    return x;
  }
  // A whole number in lowest..highest (1.5 was taken as 1).
  double whole(const char* key, double lowest, double highest, bool required = true, double otherwise = 0) {
    const double x = number(key, lowest, highest, required, otherwise);
    if (ok_ && std::floor(x) != x) fail(ErrorId::ApiBadValue, fmt::format("'{}' must be a whole number", key));
    return x;
  }
  std::string text(const char* key, std::size_t max_chars, bool required = true) {
    const json* v = required ? field(key) : optional_field(key);
    if (!v) return {};
    if (!v->is_string()) return fail(ErrorId::ApiBadValue, fmt::format("'{}' must be a string", key)), std::string();
    std::string s = v->get<std::string>();
    if (s.size() > max_chars) return fail(ErrorId::ApiBadValue, fmt::format("'{}' is longer than {} characters", key, max_chars)), std::string();
    if (s.find_first_of("\r\n") != std::string::npos)
      return fail(ErrorId::ApiBadValue, fmt::format("'{}' must be one line", key)), std::string();
    return s;
  }
  // A name the scenario grammar reads as one word: an axis or a spindle.
  std::string name(const char* key) {
    std::string s = text(key, 15);
    const bool word = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
      return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
    if (ok_ && !word) fail(ErrorId::ApiBadValue, fmt::format("'{}' must be a name of letters and digits", key));
    return s;
  }
  // One of `words`.
  std::string choice(const char* key, std::initializer_list<std::string_view> words) {
    std::string s = text(key, 16);
    if (ok_ && std::find(words.begin(), words.end(), s) == words.end())
      fail(ErrorId::ApiBadValue, fmt::format("'{}' must be one of: {}", key, fmt::join(words, ", ")));
    return s;
  }

 private:
  const json* field(const char* key) {
    const json* v = optional_field(key);
    if (!v && ok_) fail(ErrorId::ApiBadValue, fmt::format("'{}' needs the field '{}'", command(), key));
    return v;
  }
  const json* optional_field(const char* key) const {
    const auto it = j_.find(key);
    return it == j_.end() || it->is_null() ? nullptr : &*it;
  }
  static std::string shown(const std::string& s) { return s.size() > 40 ? s.substr(0, 40) + "..." : s; }

  const json& j_;
  Diagnostics& diags_;
  bool ok_ = true;
};

// A parser callback that notes the first key an object has twice in
// `found` (the parser keeps the last silently: {"mask":1,"mask":512}). A
// set per object: a list searched per key made a 64 KiB object of 8,000
// keys cost the server's one thread 100 ms (issue 45's attack campaign).
json::parser_callback_t duplicate_key_finder(std::string& found) {
  auto open = std::make_shared<std::vector<std::unordered_set<std::string>>>();  // the keys of each open object
  return [open, &found](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) open->emplace_back();
    else if (event == json::parse_event_t::object_end && !open->empty()) open->pop_back();
    else if (event == json::parse_event_t::key && !open->empty()) {
      std::string key = parsed.get<std::string>();
      if (!open->back().insert(key).second && found.empty()) found = std::move(key);
    }
    return true;
  };
}

// A name the Reader checked (at most 15 characters) as an action stores it.
std::array<char, plc::kSpindleNameChars> fixed_name(const std::string& s) {
  std::array<char, plc::kSpindleNameChars> out{};
  std::copy_n(s.begin(), std::min(s.size(), out.size() - 1), out.begin());
  return out;
}

std::int8_t direction_of(const std::string& word) { return word == "+" ? 1 : word == "-" ? -1 : 0; }

// The typed action of an operator command, or nothing when `cmd` is none.
std::optional<sim::ActionPayload> operator_payload(const std::string& cmd, Reader& r) {
  using namespace sim::act;
  const auto on = [&] {
    r.only({"on"});
    return r.boolean("on");
  };
  const auto bare = [&](auto payload) {
    r.only({});
    return sim::ActionPayload(payload);
  };
  if (cmd == "cycle_start") return bare(CycleStart{});
  if (cmd == "stop") return bare(Stop{});
  if (cmd == "reset") return bare(Reset{});
  if (cmd == "feedhold") return Feedhold{on()};
  if (cmd == "single_step") return SingleStep{on()};
  if (cmd == "optional_stop") return OptionalStop{on()};
  if (cmd == "skip_mask") {
    r.only({"mask"});
    return SkipMask{static_cast<std::uint32_t>(r.whole("mask", 0, 1023))};
  }
  if (cmd == "feed_override" || cmd == "rapid_override") {
    r.only({"percent"});
    const double percent = r.number("percent", 0, 200);
    return cmd == "feed_override" ? sim::ActionPayload(FeedOverride{percent}) : sim::ActionPayload(RapidOverride{percent});
  }
  if (cmd == "spindle_override") {
    r.only({"spindle", "percent"});
    SpindleOverride o;
    o.spindle.name = fixed_name(r.name("spindle"));
    o.percent = r.number("percent", 0, 200);
    return o;
  }
  if (cmd == "mode") {
    r.only({"mode"});
    return Mode{r.choice("mode", {"manual", "automatic"}) == "manual"};
  }
  if (cmd == "jog") {
    r.only({"axis", "direction", "speed_mm_min"});
    Jog j;
    j.axis.name = fixed_name(r.name("axis"));
    j.direction = direction_of(r.choice("direction", {"+", "-", "stop"}));
    const double speed = r.number("speed_mm_min", 1e-3, 1e6, false);
    if (j.direction != 0) j.speed_mm_min = speed;  // 0: the axis's jog speed
    return j;
  }
  if (cmd == "jog_increment") {
    r.only({"axis", "direction", "step_mm"});
    JogIncrement j;
    j.axis.name = fixed_name(r.name("axis"));
    j.direction = direction_of(r.choice("direction", {"+", "-"}));
    j.step_mm = r.number("step_mm", 1e-6, 1e4);
    return j;
  }
  return std::nullopt;
}

bool other_command(const std::string& cmd, Reader& r, ApiCommand& out) {
  using K = ApiCommand::Kind;
  if (cmd == "mdi") {
    r.only({"text", "queue"});
    out.kind = K::mdi;
    out.text = r.text("text", kMaxMdiChars);
    out.queue = r.boolean("queue", false);
    if (r.ok() && out.text.find_first_not_of(" \t") == std::string::npos) r.fail(ErrorId::ApiBadValue, "'text' is empty");
  } else if (cmd == "load") {
    r.only({"program", "start_at"});
    out.kind = K::load;
    out.program = r.text("program", 1024);
    out.start_at = r.text("start_at", 128, false);
  } else if (cmd == "pause") {
    r.only({"on"});
    out.kind = K::pause;
    out.on = r.boolean("on");
  } else if (cmd == "action") {
    r.only({"line"});
    out.kind = K::action_line;
    const std::string line = r.text("line", 256);
    // An empty line has always been refused as no command at all.
    if (line.empty() && r.ok()) return false;
    out.line = fmt::format("ch={} {}", out.channel, line);  // the channel field, as the grammar writes it
  } else if (cmd == "step_cycle") {
    r.only({});
    out.kind = K::step_cycle;
  } else if (cmd == "speed") {
    r.only({"speed"});
    out.kind = K::speed;
    out.speed = r.speed("speed");
  } else {
    return false;
  }
  return true;
}

}  // namespace

std::optional<ApiCommand> parse_api_command(std::string_view body, std::size_t channels, Diagnostics& diags) {
  const SourceLoc loc{};
  if (body.size() > kMaxCommandBytes) {
    diags.add(ErrorId::ApiTooLarge, loc, fmt::format("a command is at most {} bytes", kMaxCommandBytes));
    return std::nullopt;
  }
  std::string duplicate;
  const json j = json::parse(body, duplicate_key_finder(duplicate), false);
  if (j.is_discarded() || !j.is_object()) {
    diags.add(ErrorId::ApiMalformedJson, loc, "the body is not one JSON object");
    return std::nullopt;
  }
  if (!duplicate.empty()) {
    diags.add(ErrorId::ApiMalformedJson, loc, fmt::format("the key '{}' appears twice in one object", duplicate.substr(0, 40)));
    return std::nullopt;
  }
  Reader r(j, diags);
  const auto cmd_it = j.find("command");
  if (cmd_it == j.end() || !cmd_it->is_string()) {
    diags.add(ErrorId::ApiBadValue, loc, "'command' (a string) is missing");
    return std::nullopt;
  }
  ApiCommand out;
  const double channel = r.whole("channel", 1, static_cast<double>(std::max<std::size_t>(channels, 1)), false, 1);
  out.channel = static_cast<std::uint8_t>(channel);
  const std::string cmd = cmd_it->get<std::string>();
  if (!other_command(cmd, r, out)) {
    const std::optional<sim::ActionPayload> payload = operator_payload(cmd, r);
    if (!payload) {
      if (r.ok())  // else the Reader's problem is the answer
        diags.add(ErrorId::ApiUnknownCommand, loc, fmt::format("'{}' is no command (docs/api.md)", cmd.substr(0, 40)));
      return std::nullopt;
    }
    out.kind = ApiCommand::Kind::action;
    out.action = sim::make_action(out.channel, *payload);
  }
  if (!r.ok()) return std::nullopt;
  return out;
}

}  // namespace nck::app::serve
