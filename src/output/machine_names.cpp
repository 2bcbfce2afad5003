#include "nck/output/machine_names.hpp"

#include "nck/plc/hli.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace nck::app {

std::vector<std::string> path_axis_columns(const config::Machine& m) {
  std::vector<std::string> cols, used;
  for (std::size_t c = 0; c < m.channels.size(); ++c) {
    std::vector<std::string> mine;
    for (const auto& ax : m.channels[c].axes) {
      const bool clash = std::find(used.begin(), used.end(), ax.name) != used.end();
      cols.push_back(clash ? fmt::format("{}.{}", c + 1, ax.name) : ax.name);
      mine.push_back(ax.name);
    }
    used.insert(used.end(), mine.begin(), mine.end());
  }
  return cols;
}

// In the kernel's spindle order (plc::build_spindle_map), so position i is
// TickOutput::spindles[i].
std::vector<SpindleName> machine_spindles(const config::Machine& m) {
  const plc::SpindleMap map = plc::build_spindle_map(m);
  std::vector<SpindleName> out(map.count);
  for (std::size_t k = 0; k < map.count; ++k) {
    const std::size_t c = map.first[k].channel - 1u;
    const config::ChannelSpindle& s = m.channels[c].spindles[static_cast<std::size_t>(map.first[k].index)];
    const bool open_loop = s.axis_index >= 0 && m.axes[static_cast<std::size_t>(s.axis_index)].is_speed_controlled();
    out[k] = {s.name, s.log_axis_nr, c, open_loop};
  }
  return out;
}

}  // namespace nck::app

namespace nck::app {
std::string main_spindle_designation(const config::ChannelConfig& ch) {
  for (const auto& s : ch.spindles)
    if (s.log_axis_nr == ch.main_spindle_ax_nr) return s.name;
  return ch.spindles.empty() ? std::string() : ch.spindles.front().name;
}
}  // namespace nck::app
