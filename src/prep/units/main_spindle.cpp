#include "nck/prep/units/main_spindle.hpp"

namespace nck::prep {
namespace {

const config::AxisConfig* axis_list(const config::Machine& machine, const config::ChannelConfig& channel,
                                    std::size_t spindle) {
  if (spindle >= channel.spindles.size()) return nullptr;
  const int ax = channel.spindles[spindle].axis_index;
  if (ax < 0 || static_cast<std::size_t>(ax) >= machine.axes.size()) return nullptr;
  return &machine.axes[static_cast<std::size_t>(ax)];
}

}  // namespace

MainSpindle MainSpindle::find(const config::ChannelConfig& channel, const std::vector<std::int8_t>& spindles) {
  MainSpindle m;
  for (std::size_t i = 0; i < channel.spindles.size() && i < spindles.size(); ++i) {
    if (m.kernel < 0 || channel.spindles[i].log_axis_nr == channel.main_spindle_ax_nr) {
      m.kernel = spindles[i];
      m.list_index = i;
    }
    if (channel.spindles[i].log_axis_nr == channel.main_spindle_ax_nr) break;
  }
  return m;
}

double MainSpindle::vb_max_rpm(const config::Machine& machine, const config::ChannelConfig& channel,
                               std::uint32_t stage) const {
  const config::AxisConfig* a = axis_list(machine, channel, list_index);
  return a ? a->gear(stage).max_speed_mm_s / 6.0 : 0;  // deg/s -> rpm
}

double MainSpindle::axis_vb_max_rpm(const config::Machine& machine, const config::ChannelConfig& channel) const {
  const config::AxisConfig* a = axis_list(machine, channel, list_index);
  return a ? a->gear(a->cax_gear_stage).max_speed_mm_s / 6.0 : 0;  // deg/s -> rpm
}

}  // namespace nck::prep
