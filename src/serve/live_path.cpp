#include "nck/serve/live_path.hpp"

#include <cmath>

#include <fmt/format.h>

#include "nck/serve/point_columns.hpp"

namespace nck::app::serve {
namespace {

// X, Y and Z of a channel's positions (0 where it has no such axis).
template <class Positions>
std::array<double, 3> xyz(const config::ChannelConfig& ch, const Positions& pos) {
  const std::array<int, 3> axes = backplot_axes(ch);
  std::array<double, 3> out{};
  for (std::size_t k = 0; k < 3; ++k)
    if (axes[k] >= 0) out[k] = pos[static_cast<std::size_t>(axes[k])];
  return out;
}

}  // namespace

void LivePath::take(const LiveSnapshot& s, const config::Machine& m, std::span<const ChannelPlace> places) {
  for (std::size_t ch = 0; ch < s.channel_count && ch < m.channels.size() && ch < places.size(); ++ch) {
    const LiveChannel& c = s.channels[ch];
    const Point p{xyz(m.channels[ch], c.axis_mcs), xyz(m.channels[ch], places[ch].pcs),
                  c.at.file_id == 0 ? c.at.line : 0, c.cause == kernel::CycleCause::rapid};
    std::vector<Point>& path = channels_[ch];
    // a standstill adds nothing (the page's rule: 1 µm summed over X, Y, Z)
    if (!path.empty() && std::abs(path.back().mcs[0] - p.mcs[0]) + std::abs(path.back().mcs[1] - p.mcs[1]) +
                                 std::abs(path.back().mcs[2] - p.mcs[2]) < 1e-3)
      continue;
    if (path.size() >= kMaxPoints) {
      std::size_t kept = 0;
      for (std::size_t i = 0; i < path.size(); i += 2) path[kept++] = path[i];
      path.resize(kept);
    }
    path.push_back(p);
  }
}

void LivePath::clear() {
  for (std::vector<Point>& path : channels_) path.clear();
}

std::string LivePath::json(std::size_t channel, std::uint64_t run) const {
  const std::vector<Point>& path = channels_[channel - 1];
  std::string s = fmt::format(R"({{"channel":{},"run":{},"points":{})", channel, run, path.size());
  append_point_columns(s, path);
  return s + "}";
}

}  // namespace nck::app::serve
