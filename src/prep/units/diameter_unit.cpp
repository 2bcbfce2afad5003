// G51/G52 diameter programming; see diameter_unit.hpp.
#include "nck/prep/units/diameter_unit.hpp"

#include <fmt/format.h>

#include "nck/prep/units/axis_table.hpp"

namespace nck::prep {

DiameterUnit::DiameterUnit(const config::Machine& machine, const config::ChannelConfig& channel,
                           std::size_t n_axes) {
  for (std::size_t j = 0; j < n_axes; ++j) {
    const int idx = channel.axes[j].axis_index;
    if (idx < 0) continue;
    const config::AxisConfig& ax = machine.axes[static_cast<std::size_t>(idx)];
    if (!ax.is_face_turning()) continue;
    if (ax.diameter_prog_abs) abs_axes_ |= 1u << j;
    if (ax.diameter_prog_rel) rel_axes_ |= 1u << j;
  }
}

bool DiameterUnit::takes_diameter(const nc::Block& b, std::size_t j) const {
  if (!b.modal.diameter) return false;
  return ((b.modal.absolute ? abs_axes_ : rel_axes_) >> j) & 1u;
}

double DiameterUnit::programmed_radius(const nc::Block& b, std::size_t j) const {
  const double v = *b.axes[j];
  return takes_diameter(b, j) ? v / 2 : v;
}

// G51 or G52 programmed: exactly one face-turning axis in the plane.
PlanResult DiameterUnit::check_switch(const nc::Block& b, PlannedCommand& c, const PlanContext& ctx) const {
  const PlaneAxes pa = plane_axes(b.modal.plane);
  const std::uint32_t face_axes = ctx.axes.face_axes();
  int in_plane = -1, count = 0;
  for (int k : {pa.first, pa.second}) {
    const int j = ctx.axis_named(kMainAxisNames[k]);
    if (j >= 0 && ((face_axes >> j) & 1u)) {
      in_plane = j;
      ++count;
    }
  }
  if (count != 1)
    return block_error(ErrorId::KernelNoFaceAxisInPlane, b,
                       fmt::format("G{}: {} face-turning axes in the plane G{}; exactly one is needed",
                                   b.modal.diameter ? 51 : 52, count, static_cast<int>(b.modal.plane)));
  const std::uint32_t bit = 1u << in_plane;
  if (b.modal.diameter && !((abs_axes_ | rel_axes_) & bit))
    (void)c.attach_within(
        kernel::Warning{{ErrorId::KernelDiameterNotConfigured,
                         ctx.store.add_message(fmt::format("G51: {} has neither kenngr.durchm_prog_abs nor "
                                                           "durchm_prog_rel; its positions stay radii",
                                                           ctx.channel.axes[static_cast<std::size_t>(in_plane)].name)),
                         {}}},
        PlannedCommand::kMaxWarnings);
  return {};
}

PlanResult DiameterUnit::check(const nc::Block& b, PlannedCommand& c, const PlanContext& ctx) {
  const bool switched = b.modal.diameter != on_;
  on_ = b.modal.diameter;
  if (switched)
    if (auto r = check_switch(b, c, ctx); !r) return r;
  if (!b.modal.diameter) return {};
  if (b.hash && (std::holds_alternative<nc::PSet>(*b.hash) || std::holds_alternative<nc::PReset>(*b.hash)))
    return block_error(ErrorId::KernelPresetInDiameter, b, "#PSET/#PRESET while G51 is active");
  if (!b.modal.absolute) return {};
  for (std::size_t j = 0; j < ctx.n_axes; ++j)
    if (b.axes[j] && *b.axes[j] < 0 && takes_diameter(b, j))
      return block_error(ErrorId::KernelNegativeDiameter, b,
                         fmt::format("{}{:g} under G51: a diameter cannot be negative", ctx.channel.axes[j].name,
                                     *b.axes[j]));
  return {};
}

}  // namespace nck::prep
