#include "nck/report/backplot_axes.hpp"

#include <algorithm>

namespace nck::app {

bool is_rotary_name(const std::string& name) {
  const char c = name.empty() ? 'X' : name[0];
  return c == 'A' || c == 'B' || c == 'C';
}

std::array<int, 3> backplot_axes(const config::ChannelConfig& ch) {
  std::array<int, 3> axis{-1, -1, -1};
  const auto& axes = ch.axes;
  static constexpr const char* kMain[] = {"X", "Y", "Z"};
  for (std::size_t j = 0; j < axes.size(); ++j)
    for (int a = 0; a < 3; ++a)
      if (axes[j].name == kMain[a] && axis[a] < 0) axis[a] = static_cast<int>(j);
  for (int a = 0; a < 3; ++a)
    for (std::size_t j = 0; j < axes.size() && axis[a] < 0; ++j)
      if (!is_rotary_name(axes[j].name) && std::find(axis.begin(), axis.end(), static_cast<int>(j)) == axis.end())
        axis[a] = static_cast<int>(j);
  return axis;
}

SoftLimits backplot_limits(const config::Machine& m, const config::ChannelConfig& ch, const std::array<int, 3>& axis) {
  static const config::AxisConfig kNoAxisList;  // the planner's defaults (AxisTable)
  SoftLimits out;
  for (int a = 0; a < 3; ++a) {
    if (axis[a] < 0) continue;
    const int idx = ch.axes[static_cast<std::size_t>(axis[a])].axis_index;
    const config::AxisConfig& ax = idx >= 0 ? m.axes[static_cast<std::size_t>(idx)] : kNoAxisList;
    out.min_mm[a] = ax.sw_limit_neg;
    out.max_mm[a] = ax.sw_limit_pos;
  }
  return out;
}

}  // namespace nck::app
