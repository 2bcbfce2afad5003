#pragma once
// What the scenario grammar accepts for an action's values, and how it says
// that a value is wrong: one place for the scenario parser, which checks a
// line's words, for check_operator_action, which checks the typed actions
// nck serve and the Python session build, and for the Python session, which
// refuses values an action cannot hold (a name too long, a mask beyond 32 bits).
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "nck/config/machine.hpp"
#include "nck/sim/scenario.hpp"

namespace nck::sim::words {

inline bool valid_channel_number(double v) {
  return v >= 1 && v <= static_cast<double>(config::kMaxChannels) && v == std::floor(v);
}
inline std::string not_a_channel(std::string_view shown) {
  return fmt::format("'{}' is not a channel number; write a whole number 1..{}", shown, config::kMaxChannels);
}

inline bool valid_percent(double v) { return v >= 0 && v <= kMaxOverridePercent; }
inline std::string not_a_percent(std::string_view shown) {
  return fmt::format("'{}' is not an override; write a percentage from 0 to {}", shown, kMaxOverridePercent);
}

inline bool valid_axis_name(std::string_view s) {
  return !s.empty() && s.size() < plc::kSpindleNameChars && std::isalpha(static_cast<unsigned char>(s[0]));
}
inline std::string not_an_axis(std::string_view shown) {
  return fmt::format("'{}' is not an axis name; write e.g. X", shown);
}

inline std::string not_a_spindle(std::string_view shown) {
  return fmt::format("'{}' is not a spindle name; write S or S followed by letters, digits "
                     "or _ (at most {} characters), e.g. S1",
                     shown, plc::kSpindleNameChars - 1);
}

inline std::string not_a_jog_direction(std::string_view shown, bool stop_allowed) {
  return fmt::format("'{}' is not a jog direction; write {}", shown, stop_allowed ? "+, - or stop" : "+ or -");
}
inline std::string not_a_jog_speed(std::string_view shown) {
  return fmt::format("'{}' is not a jog speed; write mm/min > 0, e.g. 600", shown);
}
inline std::string not_a_jog_step(std::string_view shown) {
  return fmt::format("'{}' is not a jog step; write mm > 0, e.g. 0.1", shown);
}
inline std::string not_a_mode(std::string_view shown) {
  return fmt::format("'{}' is not a mode; write manual or automatic", shown);
}

inline constexpr std::uint32_t kAllSkipLevels = 0x3FF;
inline std::string not_a_skip_mask(std::string_view shown) {
  return fmt::format("'{}' is not a skip mask; write 0 to 1023 (0x3FF): bit 0 = /1 ... bit 9 = /10", shown);
}

inline constexpr std::string_view kMissingMdiText = "the NC block to run (e.g. G1 X10 F1000)";

template <std::size_t N>
void copy_name(std::string_view text, std::array<char, N>& to) {
  const std::size_t n = std::min(text.size(), N - 1);
  std::copy_n(text.begin(), n, to.begin());
  to[n] = '\0';
}

}  // namespace nck::sim::words
