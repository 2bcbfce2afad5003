#pragma once
// The rapid traverse override (P-CHAN-00181 g00_override_mode): which of
// the channel's two HLI overrides scales a G0 block. Feed blocks always take
// the feed override.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string_view>

namespace nck {

enum class RapidOverrideMode : std::uint8_t {
  not_used,          // 0: the feed override acts on G0 too (ISG default)
  minimum_of_g0_g1,  // 1: G0 takes the smaller of feed and rapid override
  active,            // 2: G0 takes the rapid override only
  active_extended,   // 3: as active, and continuous jog takes the rapid override
};

// The list spelling ("ACTIVE" or "2"); nullopt for anything else.
inline std::optional<RapidOverrideMode> rapid_override_mode_from(std::string_view s) {
  constexpr std::string_view kNames[] = {"NOT_USED", "MINIMUM_OF_G0_G1", "ACTIVE", "ACTIVE_EXTENDED"};
  for (std::uint8_t i = 0; i < 4; ++i)
    if (s == kNames[i] || (s.size() == 1 && s[0] == '0' + i)) return static_cast<RapidOverrideMode>(i);
  return std::nullopt;
}

// The factor (0..1) a G0 block runs at, from the two overrides in percent
// (each clamped to 0..100 as the feed override is). rt
inline double rapid_override_factor(RapidOverrideMode mode, double feed_pct, double rapid_pct) noexcept {
  const double feed = std::clamp(feed_pct, 0.0, 100.0) / 100.0;
  const double rapid = std::clamp(rapid_pct, 0.0, 100.0) / 100.0;
  switch (mode) {
    case RapidOverrideMode::not_used: return feed;
    case RapidOverrideMode::minimum_of_g0_g1: return std::min(feed, rapid);
    case RapidOverrideMode::active:
    case RapidOverrideMode::active_extended: return rapid;
  }
  return feed;
}

}  // namespace nck
