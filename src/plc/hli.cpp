#include "nck/plc/hli.hpp"

#include <cmath>
#include <limits>

namespace nck::plc {

SpindleMap build_spindle_map(const config::Machine& m) {
  SpindleMap map;
  for (auto& row : map.index) row.fill(kNoSpindle);
  // Logical axis number of each HLI object, to share objects across channels.
  std::array<std::uint32_t, kMaxHliSpindles> owner_nr{};
  for (std::size_t c = 0; c < m.channels.size() && c < kMaxHliChannels; ++c) {
    const auto& spindles = m.channels[c].spindles;
    for (std::size_t i = 0; i < spindles.size() && i < config::kMaxSpindles; ++i) {
      const std::uint32_t nr = spindles[i].log_axis_nr;
      std::int8_t found = kNoSpindle;
      for (std::size_t k = 0; k < map.count; ++k)
        if (nr != 0 && owner_nr[k] == nr) found = static_cast<std::int8_t>(k);
      if (found == kNoSpindle && map.count < kMaxHliSpindles) {
        owner_nr[map.count] = nr;
        map.first[map.count] = {static_cast<std::uint8_t>(c + 1), static_cast<std::int8_t>(i)};
        found = static_cast<std::int8_t>(map.count++);
      }
      map.index[c][i] = found;
    }
  }
  return map;
}

HliImage make_hli_image(const config::Machine& m) {
  HliImage img;
  img.ads_32_bit_comp_mode = m.ads_32_bit_comp_mode;
  for (auto& s : img.spindle_control) s.override_percent = m.sim.spindle_override_percent;
  for (auto& c : img.channel) c.feed_override_percent = m.sim.feed_override_percent;
  return img;
}

namespace {

// Rounds v and clamps it to [lo, hi]; NaN becomes 0. Flags any clamping.
HliPosition round_clamped(double v, double lo, double hi) noexcept {
  if (std::isnan(v)) return {0, true};
  if (v <= lo) return {static_cast<std::int64_t>(lo), v < lo};
  if (v >= hi) return {static_cast<std::int64_t>(hi), v > hi};
  return {std::llround(v), false};
}

}  // namespace

HliPosition encode_position(double pos_deg, PositionFormat f) noexcept {
  if (f == PositionFormat::scaled_32bit)
    return round_clamped(pos_deg * kScaled32UnitsPerDeg,
                         static_cast<double>(std::numeric_limits<std::int32_t>::min()),
                         static_cast<double>(std::numeric_limits<std::int32_t>::max()));
  // +-2^62 keeps the double -> int64 conversion exact and in range.
  constexpr double kLimit = 4611686018427387904.0;
  return round_clamped(pos_deg * kHighRes64UnitsPerDeg, -kLimit, kLimit);
}

double decode_position(std::int64_t raw, PositionFormat f) noexcept {
  const double scale =
      f == PositionFormat::scaled_32bit ? kScaled32UnitsPerDeg : kHighRes64UnitsPerDeg;
  return static_cast<double>(raw) / scale;
}

std::int32_t to_hli_speed(double rpm) noexcept {
  // 1 rpm = 360 deg / 60 s = 6 deg/s = 6000 * 0.001 deg/s
  const HliPosition r = round_clamped(rpm * 6000.0,
                                      static_cast<double>(std::numeric_limits<std::int32_t>::min()),
                                      static_cast<double>(std::numeric_limits<std::int32_t>::max()));
  return static_cast<std::int32_t>(r.raw);
}

}  // namespace nck::plc
