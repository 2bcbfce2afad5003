// Kernel state variables the decoder reads; see state_variables.hpp.
#include "nck/prep/state_variables.hpp"

#include <string>
#include <utility>
#include <vector>

namespace nck::prep {
namespace {

constexpr std::string_view kRotation = "V.G.ROT_";
constexpr std::string_view kAxisVariables[] = {"V.G.NP_AKT.V.", "V.A.MEIN.", "V.A.ABS."};

std::optional<double> value_named(const std::vector<std::pair<std::string, double>>& values,
                                  std::string_view name) {
  for (const auto& [n, v] : values)
    if (n == name) return v;
  return std::nullopt;
}

// ACTIVE, ANGLE, CENTER1, CENTER2 of #ROTATION (0 while it is off).
std::optional<double> rotation_variable(std::string_view field, const ChannelFrames& frames, Plane plane) {
  frames::OffsetEntry rotation{};
  bool active = false;
  for (const frames::OffsetEntry& e : frames.active())
    if (e.kind == frames::OffsetKind::rotation) {
      rotation = e;
      active = true;
    }
  const PlaneAxes axes = plane_axes(plane);
  if (field == "ACTIVE") return active ? 1.0 : 0.0;
  if (field == "ANGLE") return rotation.angle_deg[2];
  if (field == "CENTER1") return rotation.values_mm[static_cast<std::size_t>(axes.first)];
  if (field == "CENTER2") return rotation.values_mm[static_cast<std::size_t>(axes.second)];
  return std::nullopt;
}

// NP_AKT: the zero offset selected; MEIN: the G101 offset selected; ABS:
// the program position after the last block, in the active coordinate system.
std::optional<double> axis_variable(std::string_view key, const ChannelFrames& frames,
                                   const config::ChannelConfig& channel, const motion::AxisVector& pcs,
                                   std::size_t n_axes) {
  for (std::string_view prefix : kAxisVariables) {
    if (!key.starts_with(prefix)) continue;
    const std::string_view axis = key.substr(prefix.size());
    if (prefix == "V.A.ABS.") {
      for (std::size_t j = 0; j < n_axes; ++j)
        if (channel.axes[j].name == axis) return pcs[j];
      return std::nullopt;
    }
    const frames::OffsetKind kind = prefix == "V.A.MEIN." ? frames::OffsetKind::measure : frames::OffsetKind::zero;
    return value_named(frames.values_of(kind, true), axis);
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> read_state_variable(std::string_view key, const ChannelFrames& frames,
                                          const config::ChannelConfig& channel, const motion::AxisVector& pcs,
                                          std::size_t n_axes, Plane plane) {
  const config::ToolRecord* tool = frames.tool_in_force();
  if (key == "V.G.WZ_AKT.NR") return frames.tool_number();
  if (key == "V.G.WZ_AKT.L") return tool ? tool->length_mm : 0.0;
  if (key == "V.G.WZ_AKT.R") return tool ? tool->radius_mm : 0.0;
  if (key.starts_with(kRotation)) return rotation_variable(key.substr(kRotation.size()), frames, plane);
  return axis_variable(key, frames, channel, pcs, n_axes);
}

}  // namespace nck::prep
