// Tool, zero-offset, clamp-offset and simulation lists -> model.
#include <fmt/format.h>

#include "build.hpp"

namespace nck::config::detail {
namespace {

using Row = AxisArray;

// Groups of "<prefix>[i].achse[j].<field>" as rows of axis values.
std::vector<Row> read_groups(const ParamList& l, std::string_view prefix, std::string_view field) {
  std::vector<Row> rows;
  auto groups = l.indices(fmt::format("{}[", prefix));
  if (groups.empty()) return rows;
  rows.resize(groups.back() + 1, Row{});
  for (auto i : groups)
    for (auto j : l.indices(fmt::format("{}[{}].achse[", prefix, i), 1))
      rows[i][j] = l.num(fmt::format("{}[{}].achse[{}].{}", prefix, i, j, field), 0);
  return rows;
}

}  // namespace

std::vector<ToolRecord> build_tools(const ParamList& l, Diagnostics& d) {
  std::vector<ToolRecord> tools;
  auto numbers = l.indices("wz[");
  if (numbers.empty()) return tools;
  tools.resize(numbers.back() + 1);  // index = tool (D) number; record 0 stays all zero
  for (auto i : numbers) {
    auto k = [i](std::string_view r) { return fmt::format("wz[{}].{}", i, r); };
    ToolRecord& t = tools[i];
    t.given = true;
    // Geometry is in 0.1 um, or 0.0001 inch when mass_einheit is 1.
    double unit = l.u32(k("mass_einheit"), 0) == 1 ? 25.4 : 1.0;
    t.length_mm = l.num(k("laenge"), 0) * unit;
    t.radius_mm = l.num(k("radius"), 0) * unit;
    for (auto j : l.indices(k("ax_versatz["), 1))
      t.axis_offset_mm[j] = l.num(fmt::format("wz[{}].ax_versatz[{}]", i, j), 0) * unit;
    t.tool_fixed = l.flag(k("tool_fixed"), false);
    t.log_ax_nr_spdl = l.u32(k("log_ax_nr_spdl"), 0);
    t.vb_min_rpm = l.num(k("vb_min"), 0);
    t.vb_max_rpm = l.num(k("vb_max"), 1.0 / 6000.0);
    t.a_max_deg_s2 = l.num(k("a_max"), 1);
    t.typ = l.u32(k("typ"), 0);
    t.cutting_edge_pos = l.u32(k("srk_lage"), 0);
    cross_check(l, k("vb_min"), k("vb_max"), t.vb_min_rpm <= t.vb_max_rpm,
                fmt::format("{} must not exceed {}", listed(l, k("vb_min"), t.vb_min_rpm),
                            listed(l, k("vb_max"), t.vb_max_rpm)), d);
  }
  return tools;
}

ZeroOffsets build_zero(const ParamList& l) {
  ZeroOffsets z;
  z.g53_available = l.flag("g53_verfuegbar", false);
  z.default_index = l.u32("default_index", 0);
  z.versch = read_groups(l, "np_grp", "versch");
  auto inactive = read_groups(l, "np_grp", "inaktiv");
  std::size_t groups = std::max(z.versch.size(), inactive.size());
  // G54..G59 always exist so that selecting them never indexes past the table.
  groups = std::max<std::size_t>(groups, 7);
  z.versch.resize(groups, Row{});
  z.inaktiv.resize(groups);
  for (std::size_t i = 0; i < inactive.size(); ++i)
    for (std::size_t j = 0; j < kMaxAxes; ++j) z.inaktiv[i][j] = inactive[i][j] != 0;
  return z;
}

ClampOffsets build_clamp(const ParamList& l) {
  ClampOffsets c;
  c.versatz = read_groups(l, "pzv_grp", "versatz");
  if (c.versatz.empty()) c.versatz.resize(1, Row{});  // group 0 = no clamp offset
  return c;
}

SimConfig build_sim(const ParamList& l) {
  SimConfig s;
  s.plc_ack_delay_s = l.num("plc_ack_delay_ms", s.plc_ack_delay_s);
  for (auto n : l.indices("m_ack_delay_ms["))
    s.m_ack_delay_s.emplace_back(n, l.num(fmt::format("m_ack_delay_ms[{}]", n), s.plc_ack_delay_s));
  s.spindle_ack_delay_s = l.num("spindle_ack_delay_ms", s.spindle_ack_delay_s);
  s.gear_change_time_s = l.num("gear_change_time_ms", s.gear_change_time_s);
  s.tool_change_time_s = l.num("tool_change_time_ms", s.tool_change_time_s);
  s.drive_speed_time_constant_s = l.num("drive.speed_time_constant_ms", s.drive_speed_time_constant_s);
  s.feed_override_percent = l.num("feed_override_percent", s.feed_override_percent);
  s.spindle_override_percent = l.num("spindle_override_percent", s.spindle_override_percent);
  auto surface = l.text("sensor.surface", "FLAT");
  s.surface = surface == "SINE" ? SurfaceKind::sine
              : surface == "STEP" ? SurfaceKind::step
              : surface == "RAMP" ? SurfaceKind::ramp
                                  : SurfaceKind::flat;
  s.surface_axis = l.text("sensor.surface_axis", s.surface_axis);
  s.surface_height_mm = l.num("sensor.surface_height", s.surface_height_mm);
  s.surface_amplitude_mm = l.num("sensor.surface_amplitude", s.surface_amplitude_mm);
  s.surface_wavelength_mm = l.num("sensor.surface_wavelength", s.surface_wavelength_mm);
  s.surface_start_mm = l.num("sensor.surface_start", s.surface_start_mm);
  s.noise_sigma_mm = l.num("sensor.noise_sigma", s.noise_sigma_mm);
  s.noise_seed = l.u32("sensor.noise_seed", s.noise_seed);
  s.sensor_delay_cycles = l.u32("sensor.delay_cycles", s.sensor_delay_cycles);
  auto fault = l.text("sensor.fault", "NONE");
  s.fault = fault == "DROPOUT" ? SensorFault::dropout
            : fault == "JUMP"  ? SensorFault::jump
            : fault == "FREEZE" ? SensorFault::freeze
                                : SensorFault::none;
  s.fault_time_s = l.num("sensor.fault_time_ms", s.fault_time_s);
  s.fault_value_mm = l.num("sensor.fault_value", s.fault_value_mm);
  s.fault_cycles = l.u32("sensor.fault_cycles", s.fault_cycles);
  s.surface_tilt_deg = l.num("sensor.surface_tilt", s.surface_tilt_deg);
  s.sensor_tool_axis = l.text("sensor.tool_axis", s.sensor_tool_axis);
  s.hole_start_mm = l.num("sensor.hole_start", s.hole_start_mm);
  s.hole_length_mm = l.num("sensor.hole_length", s.hole_length_mm);
  s.hole_depth_mm = l.num("sensor.hole_depth", s.hole_depth_mm);
  s.probe_axis = l.text("probe.axis", s.probe_axis);
  s.probe_position_mm = l.num("probe.position", s.probe_position_mm);
  return s;
}

}  // namespace nck::config::detail
