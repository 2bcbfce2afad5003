#include "nck/prep/decoder_setup.hpp"

#include <fmt/format.h>

namespace nck::prep {

nc::DecoderConfig decoder_config(const config::Machine& m, std::size_t ch) {
  nc::DecoderConfig d;
  d.main_spindle.clear();
  const config::ChannelConfig& c = m.channels.at(ch);
  for (const auto& ax : c.axes) d.axis_names.push_back(ax.name);
  for (const auto& s : c.spindles) {
    d.spindle_names.push_back(s.name);
    d.spindle_log_axis_numbers.push_back(static_cast<int>(s.log_axis_nr));  // #MAIN SPINDLE [nr]
    if (s.log_axis_nr == c.main_spindle_ax_nr) d.main_spindle = s.name;
  }
  if (d.main_spindle.empty() || c.main_spindle_ax_nr == 0)
    d.main_spindle = c.spindles.empty() ? std::string() : c.spindles.front().name;
  d.main_spindle_name = c.main_spindle_name.empty() ? "S" : c.main_spindle_name;
  // The one place machine data switches decoder functions on or off.
  d.dist_ctrl_available = c.dist_ctrl_enabled();
  d.use_cached_files = (c.decoder_function & config::decoder_fct::FCT_USE_CACHED_FILES) != 0;
  d.max_cache_number = c.max_cache_number;
  d.max_cache_size_kb = c.max_cache_size_kb;
  d.cycle_dirs = m.cycle_paths;
  return d;
}

std::vector<std::pair<std::string, double>> initial_variables(const config::Machine& m, std::size_t ch,
                                                              std::uint32_t clamp_index) {
  std::vector<std::pair<std::string, double>> vars{{"V.G.AKT_PLATZ", static_cast<double>(clamp_index)}};
  if (ch >= m.channel_data.size()) return vars;
  const config::ChannelConfig& c = m.channels.at(ch);
  const auto& groups = m.channel_data[ch].zero.versch;
  for (std::size_t i = 0; i < groups.size(); ++i)
    for (std::size_t j = 0; j < c.axes.size() && j < groups[i].size(); ++j)
      if (groups[i][j] != 0) vars.emplace_back(fmt::format("V.G.NP[{}].V.{}", i, c.axes[j].name), groups[i][j]);
  return vars;
}

}  // namespace nck::prep
