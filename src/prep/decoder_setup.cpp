#include "nck/prep/decoder_setup.hpp"

#include <fmt/format.h>

#include "nck/core/axis_name.hpp"
#include "nck/plc/hli.hpp"

namespace nck::prep {

nc::DecoderConfig decoder_config(const config::Machine& m, std::size_t ch) {
  nc::DecoderConfig d;
  d.main_spindle.clear();
  const config::ChannelConfig& c = m.channels.at(ch);
  for (const auto& ax : c.axes) d.axis_names.push_back(ax.name);
  if (c.c_axis >= 0 && static_cast<std::size_t>(c.c_axis) < d.axis_names.size()) {
    // The program names the C axis by #CAX, else by P-CHAN-00010 (none: only after #CAX [S, name]).
    d.c_axis = c.c_axis;
    d.c_axis_default_name = c.default_ax_name_of_spindle;
    d.axis_names[static_cast<std::size_t>(c.c_axis)] = c.default_ax_name_of_spindle;
  }
  if (c.use_alias_names)  // P-CHAN-00253: A1..A32 of the axis lists (P-AXIS-00297)
    for (const auto& ax : c.axes) {
      const bool listed = ax.axis_index >= 0 && static_cast<std::size_t>(ax.axis_index) < m.axes.size();
      const std::string alias = listed ? m.axes[static_cast<std::size_t>(ax.axis_index)].name : std::string();
      d.axis_aliases.push_back(is_alias_axis_name(alias) ? alias : std::string());
    }
  for (const auto& s : c.spindles) {
    d.spindle_names.push_back(s.name);
    d.spindle_log_axis_numbers.push_back(static_cast<int>(s.log_axis_nr));  // #MAIN SPINDLE [nr]
    if (s.log_axis_nr == c.main_spindle_ax_nr) d.main_spindle = s.name;
  }
  if (d.main_spindle.empty() || c.main_spindle_ax_nr == 0)
    d.main_spindle = c.spindles.empty() ? std::string() : c.spindles.front().name;
  d.main_spindle_name = c.main_spindle_name.empty() ? "S" : c.main_spindle_name;
  d.slope_default = c.slope_profile;
  d.every_block = c.single_step_mode == 1;
  d.multi_dimension_in_block = c.multi_dimension_in_block;
  d.multi_axes_in_block = c.multi_axes_in_block;
  // The one place machine data switches decoder functions on or off.
  // P-CHAN-00507/00508: only the functions of the run's start mode.
  const std::uint32_t fct = c.decoder_functions();
  d.dist_ctrl_available = (fct & config::decoder_fct::FCT_3D_DIST_CTRL) != 0;
  d.use_cached_files = (fct & config::decoder_fct::FCT_USE_CACHED_FILES) != 0;
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

std::vector<std::int8_t> kernel_spindles(const config::Machine& m, std::size_t ch) {
  const plc::SpindleMap map = plc::build_spindle_map(m);
  std::vector<std::int8_t> out;
  for (std::size_t i = 0; i < m.channels[ch].spindles.size(); ++i)
    out.push_back(map.at(ch + 1, static_cast<std::int32_t>(i)));
  return out;
}

}  // namespace nck::prep
