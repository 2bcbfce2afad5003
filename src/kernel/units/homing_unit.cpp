#include "homing_unit.hpp"

#include <bit>

namespace nck::kernel {

void HomingUnit::require(std::size_t j, std::optional<std::uint32_t> message) noexcept {
  if (j >= kMaxAxes) return;
  required_ |= 1u << j;
  messages_[j] = message;
}

std::optional<ev::Error> HomingUnit::start(const Command& c, const HomeAxes* home, const motion::Segment& seg,
                                           const AffineMap* map) noexcept {
  pending_ = home ? home->mask : 0u;
  // G74 itself moves unhomed axes: that is what it is for.
  if (home || !c.is<Motion>()) return std::nullopt;
  const std::uint32_t missing = required_ & ~homed_;
  if (missing == 0) return std::nullopt;
  const std::uint32_t refused = moved_axes(seg, map) & missing;
  if (refused == 0) return std::nullopt;
  const auto j = static_cast<std::size_t>(std::countr_zero(refused));
  ev::Error e{{ErrorId::KernelAxisNotHomed, messages_[j], {}}};
  return e;
}

std::uint32_t moved_axes(const motion::Segment& seg, const AffineMap* map) noexcept {
  const std::size_t n = seg.axis_count();
  motion::AxisVector first{}, p{}, m{};
  const auto at = [&](double s_mm, motion::AxisVector& out) {
    seg.point_at(s_mm, p);
    if (map) map->apply(p, out, n);
    else out = p;
  };
  at(0, first);
  std::uint32_t mask = 0;
  // The end and the quarter points: a circle's axes change at one of them
  // even where the end equals the start.
  const double len = seg.length();
  for (double f : {0.25, 0.5, 0.75, 1.0}) {
    at(f * len, m);
    for (std::size_t j = 0; j < n && j < kMaxAxes; ++j)
      if (m[j] != first[j]) mask |= 1u << j;
  }
  return mask;
}

}  // namespace nck::kernel
