// Kernel state variables the decoder reads (nc::KernelStateReader): the
// tool, rotation, zero offset, measuring offset and position in force after
// every block planned so far, which is what the reading block sees.
#include "nck/prep/planner.hpp"

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

}  // namespace

std::optional<double> Planner::read(std::string_view key) const {
  const config::ToolRecord* tool = frames_.tool_in_force();
  if (key == "V.G.WZ_AKT.NR") return frames_.tool_number();
  if (key == "V.G.WZ_AKT.L") return tool ? tool->laenge_mm : 0.0;
  if (key == "V.G.WZ_AKT.R") return tool ? tool->radius_mm : 0.0;
  if (key.starts_with(kRotation)) return rotation_variable(key.substr(kRotation.size()));
  return axis_variable(key);
}

// ACTIVE, ANGLE, CENTER1, CENTER2 of #ROTATION (0 while it is off).
std::optional<double> Planner::rotation_variable(std::string_view field) const {
  frames::OffsetEntry rotation{};
  bool active = false;
  for (const frames::OffsetEntry& e : frames_.active())
    if (e.kind == frames::OffsetKind::rotation) {
      rotation = e;
      active = true;
    }
  const PlaneAxes plane = plane_axes(modal_.plane);
  if (field == "ACTIVE") return active ? 1.0 : 0.0;
  if (field == "ANGLE") return rotation.angle_deg[2];
  if (field == "CENTER1") return rotation.values_mm[static_cast<std::size_t>(plane.first)];
  if (field == "CENTER2") return rotation.values_mm[static_cast<std::size_t>(plane.second)];
  return std::nullopt;
}

// NP_AKT: the zero offset selected; MEIN: the G101 offset selected; ABS:
// the program position after the last block, in the active coordinate system.
std::optional<double> Planner::axis_variable(std::string_view key) const {
  for (std::string_view prefix : kAxisVariables) {
    if (!key.starts_with(prefix)) continue;
    const std::string_view axis = key.substr(prefix.size());
    if (prefix == "V.A.ABS.") {
      for (std::size_t j = 0; j < n_axes_; ++j)
        if (channel_.axes[j].name == axis) return pcs_[j];
      return std::nullopt;
    }
    const frames::OffsetKind kind = prefix == "V.A.MEIN." ? frames::OffsetKind::measure : frames::OffsetKind::zero;
    return value_named(frames_.values_of(kind, true), axis);
  }
  return std::nullopt;
}

}  // namespace nck::prep
