// Tool, zero-offset, clamp-offset and simulation list keys.
// Row layout as in registry_table_channel.cpp.
#include "registry_internal.hpp"

namespace nck::config::detail {
namespace {

using T = ParamType;
constexpr auto W = ListKind::tool;
constexpr auto Z = ListKind::zero;
constexpr auto K = ListKind::clamp;
constexpr auto M = ListKind::sim;
constexpr char kLen[] = "0.1 µm (0.0001 inch)";

constexpr ParamInfo kTable[] = {
    // ---- tool list (wz[i], i = tool / D number) ------------------------------
    {"wz[].typ", "P-TOOL-00001", W, T::integer, 0, kU16, 0, 1, "—", "—", "Tool type; accepted.", {1000}},
    {"wz[].srk_lage", "P-TOOL-00002", W, T::integer, 0, 9, 0, 1, "—", "—", "Cutting-edge position 1..9 of a turning tool (typ 1) in the Z X plane; 0 = none (nose centre).", {1000}},
    {"wz[].laenge", "P-TOOL-00003", W, T::integer, kS32Min, kS32, 0, 1e-4, kLen, "mm", "Tool length.", {1000}},
    {"wz[].radius", "P-TOOL-00004", W, T::integer, kS32Min, kS32, 0, 1e-4, kLen, "mm", "Tool radius.", {1000}},
    {"wz[].ax_versatz[]", "P-TOOL-00006", W, T::integer, kS32Min, kS32, 0, 1e-4, kLen, "mm", "Offset of channel axis j.", {1000, 32}},
    {"wz[].mass_einheit", "P-TOOL-00008", W, T::integer, 0, 1, 0, 1, "—", "—", "Unit of the geometry values: 0 mm, 1 inch.", {1000}},
    {"wz[].tool_fixed", "P-TOOL-00010", W, T::boolean, 0, 1, 0, 1, "—", "—", "Offsets act in machine-axis directions.", {1000}},
    {"wz[].log_ax_nr_spdl", "P-TOOL-00012", W, T::integer, 0, kU16, 0, 1, "—", "—", "Spindle that takes this tool's dynamic limits (0 = none).", {1000}},
    {"wz[].vb_min", "P-TOOL-00013", W, T::real, 0, 2000000000, 0, 1.0 / 6000.0, "0.001°/s", "rpm", "Lowest tool speed (endless rotation).", {1000}},
    {"wz[].vb_max", "P-TOOL-00014", W, T::real, 1, 2000000000, 1, 1.0 / 6000.0, "0.001°/s", "rpm", "Highest tool speed.", {1000}},
    {"wz[].a_max", "P-TOOL-00015", W, T::real, 1, 1000000000, 1, 1, "°/s²", "deg/s²", "Highest spindle acceleration with this tool.", {1000}},
    // ---- zero-offset list ------------------------------------------------------
    {"g53_verfuegbar", "P-ZERO-00001", Z, T::boolean, 0, 1, 0, 1, "—", "—", "Group 0 (G53) is a usable offset instead of 'no offset'."},
    {"default_index", "P-ZERO-00002", Z, T::integer, 0, 96, 0, 1, "—", "—", "Group active after start (0 = G53, 1 = G54 ...)."},
    {"np_grp[].achse[].versch", "P-ZERO-00003", Z, T::integer, kS32Min, kS32, 0, 1e-4, "0.1 µm · 0.0001°", "mm · deg", "Offset of channel axis j in group i (1 = G54 ... 6 = G59).", {97, 32}},
    {"np_grp[].achse[].inaktiv", "P-ZERO-00004", Z, T::boolean, 0, 1, 0, 1, "—", "—", "Offset of axis j in group i is ignored.", {97, 32}},
    // ---- clamp-offset list -----------------------------------------------------
    {"pzv_grp[].achse[].versatz", "P-CLMP-00001", K, T::integer, kS32Min, kS32, 0, 1e-4, "0.1 µm · 0.0001°", "mm · deg", "Clamp offset of channel axis j in group i.", {150, 32}},
    // ---- simulation list (nck) -------------------------------------------------
    {"plc_ack_delay_ms", "nck", M, T::real, 0, 3600000, 10, 1e-3, "ms", "s", "Delay before the simulated PLC acknowledges an M function."},
    {"m_ack_delay_ms[]", "nck", M, T::real, 0, 3600000, 10, 1e-3, "ms", "s", "Acknowledgement delay for M function n (overrides plc_ack_delay_ms).", {1000}},
    {"spindle_ack_delay_ms", "nck", M, T::real, 0, 3600000, 10, 1e-3, "ms", "s", "PLC acknowledgement delay of spindle functions with PLC_INFO."},
    {"gear_change_time_ms", "nck", M, T::real, 0, 3600000, 500, 1e-3, "ms", "s", "Time the PLC needs to shift a gear stage."},
    {"tool_change_time_ms", "nck", M, T::real, 0, 3600000, 0, 1e-3, "ms", "s", "Time the PLC needs to acknowledge T / M6."},
    {"drive.speed_time_constant_ms", "nck", M, T::real, 0, 10000, 20, 1e-3, "ms", "s", "First-order lag of the simulated actual spindle speed."},
    {"feed_override_percent", "nck", M, T::real, 0, 200, 100, 1, "%", "%", "Feed override at start."},
    {"spindle_override_percent", "nck", M, T::real, 0, 200, 100, 1, "%", "%", "Spindle override at start."},
    {"sensor.surface", "nck", M, T::choice, 0, 0, 0, 1, "—", "—", "Simulated workpiece surface seen by the distance sensor.", {}, "FLAT SINE STEP RAMP", "FLAT"},
    {"sensor.surface_axis", "nck", M, T::string, 0, 16, 0, 1, "—", "—", "Channel axis along which the surface height varies.", {}, {}, "X"},
    {"sensor.surface_height", "nck", M, T::integer, kS32Min, kS32, 0, 1e-4, "0.1 µm", "mm", "Surface height at the start (FLAT level)."},
    {"sensor.surface_amplitude", "nck", M, T::integer, kS32Min, kS32, 0, 1e-4, "0.1 µm", "mm", "SINE amplitude, STEP height, RAMP rise per wavelength."},
    {"sensor.surface_wavelength", "nck", M, T::integer, 1, kS32, 1000000, 1e-4, "0.1 µm", "mm", "SINE period / RAMP length."},
    {"sensor.surface_start", "nck", M, T::integer, kS32Min, kS32, 0, 1e-4, "0.1 µm", "mm", "Axis position where STEP / RAMP begins."},
    {"sensor.noise_sigma", "nck", M, T::integer, 0, kS32, 0, 1e-4, "0.1 µm", "mm", "Standard deviation of sensor noise."},
    {"sensor.noise_seed", "nck", M, T::integer, 0, kU32, 1, 1, "—", "—", "Seed of the noise generator (runs are repeatable)."},
    {"sensor.delay_cycles", "nck", M, T::integer, 0, 1000, 0, 1, "cycles", "cycles", "Dead time of the sensor signal."},
    {"sensor.fault", "nck", M, T::choice, 0, 0, 0, 1, "—", "—", "Sensor fault injected at fault_time_ms.", {}, "NONE DROPOUT JUMP FREEZE", "NONE"},
    {"sensor.fault_time_ms", "nck", M, T::real, 0, 1e9, 0, 1e-3, "ms", "s", "Simulated time at which the fault starts."},
    {"sensor.fault_value", "nck", M, T::integer, kS32Min, kS32, 0, 1e-4, "0.1 µm", "mm", "JUMP: added to the value (DROPOUT: no value at all, FREEZE: the value stays)."},
    {"sensor.fault_cycles", "nck", M, T::integer, 0, kS32, 0, 1, "cycles", "cycles", "How long the fault lasts (0 = to the end of the run)."},
    {"sensor.surface_tilt", "nck", M, T::integer, -45000, 45000, 0, 1e-3, "0.001°", "deg", "Tilt of the surface along surface_axis (added to every kind)."},
    {"sensor.hole_start", "nck", M, T::integer, kS32Min, kS32, 0, 1e-4, "0.1 µm", "mm", "Where a hole (a slot across the sheet) begins along surface_axis."},
    {"sensor.hole_length", "nck", M, T::integer, 0, kS32, 0, 1e-4, "0.1 µm", "mm", "Length of the hole along surface_axis (0 = no hole)."},
    {"sensor.hole_depth", "nck", M, T::integer, 0, kS32, 0, 1e-4, "0.1 µm", "mm", "How much farther the sensor sees inside the hole."},
    {"sensor.tool_axis", "nck", M, T::string, 0, 16, 0, 1, "—", "—", "Channel axis the sensor looks along (the tool axis).", {}, {}, "Z"},
    {"probe.axis", "nck", M, T::string, 0, 16, 0, 1, "—", "—", "Channel axis whose machine position switches the measuring probe (G100); empty: the probe never switches.", {}, {}, ""},
    {"probe.position", "nck", M, T::integer, kS32Min, kS32, 0, 1e-4, "0.1 µm", "mm", "Machine position of probe.axis at which the probe switches."},
};

}  // namespace

std::span<const ParamInfo> tool_zero_clamp_sim_table() { return kTable; }

}  // namespace nck::config::detail
