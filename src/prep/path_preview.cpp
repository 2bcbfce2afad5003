#include "nck/prep/path_preview.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace nck::prep {

// A line is one chord; an arc (or parabola) one per 5° of its turn, at
// least 4: within 0.1 % of its radius, a pixel on any screen's view of it.
std::size_t PathPreview::chords(const motion::Segment& s) {
  if (s.kind() == motion::SegmentKind::line) return 1;
  constexpr double kChordRad = 5.0 * std::numbers::pi / 180.0;
  // (a cubic span, a smoothed chord, turns by a few degrees at most: 4)
  const double turn = s.kind() == motion::SegmentKind::arc     ? std::abs(s.sweep_rad())
                      : s.kind() == motion::SegmentKind::cubic ? 0.0
                                                               : std::numbers::pi / 2;
  return std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(turn / kChordRad)), 4, 360);
}

std::array<double, 3> PathPreview::pick(const motion::AxisVector& p) const {
  std::array<double, 3> xyz{};
  for (std::size_t k = 0; k < 3; ++k)
    if (axes_[k] >= 0) xyz[k] = p[static_cast<std::size_t>(axes_[k])];
  return xyz;
}

void PathPreview::push(const motion::AxisVector& mcs, const motion::AxisVector& pcs, std::uint16_t file,
                       std::uint32_t line, bool rapid) {
  if (full()) return;
  points_.push_back({pick(mcs), pick(pcs), line, file, rapid});
}

}  // namespace nck::prep
