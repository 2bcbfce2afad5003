#include "machine_names.hpp"

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

std::vector<SpindleName> machine_spindles(const config::Machine& m) {
  std::vector<SpindleName> out;
  for (std::size_t c = 0; c < m.channels.size(); ++c)
    for (const auto& s : m.channels[c].spindles) {
      const bool known = std::any_of(out.begin(), out.end(), [&](const SpindleName& o) {
        return s.log_axis_nr != 0 ? o.log_axis_nr == s.log_axis_nr : o.name == s.name;
      });
      if (known) continue;
      const bool open_loop =
          s.axis_index >= 0 && m.axes[static_cast<std::size_t>(s.axis_index)].is_speed_controlled();
      out.push_back({s.name, s.log_axis_nr, c, open_loop});
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
