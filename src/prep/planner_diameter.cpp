// G51/G52 diameter programming (facts C11): under G51 the positions of the
// face-turning axes (kenngr.achs_mode 0x40) are diameters about the turning
// centre — G90 words when the axis sets kenngr.durchm_prog_abs, G91 words
// when it sets durchm_prog_rel. Only the programmed words are halved: the
// offsets, the set points and the trace stay radii, and I/J/K and R are
// never diameters.
#include <fmt/format.h>

#include "nck/prep/planner.hpp"

namespace nck::prep {

// setup: which axes take diameters, per dimension mode.
void Planner::setup_diameter_axes(const config::Machine& machine) {
  for (std::size_t j = 0; j < n_axes_; ++j) {
    const int idx = channel_.axes[j].axis_index;
    if (idx < 0) continue;
    const config::AxisConfig& ax = machine.axes[static_cast<std::size_t>(idx)];
    if (!ax.is_face_turning()) continue;
    face_axes_ |= 1u << j;
    if (ax.durchm_prog_abs) diameter_abs_axes_ |= 1u << j;
    if (ax.durchm_prog_rel) diameter_rel_axes_ |= 1u << j;
  }
}

bool Planner::takes_diameter(const nc::Block& b, std::size_t j) const {
  if (!b.modal.diameter) return false;
  return ((b.modal.absolute ? diameter_abs_axes_ : diameter_rel_axes_) >> j) & 1u;
}

double Planner::programmed_radius(const nc::Block& b, std::size_t j) const {
  const double v = *b.axes[j];
  return takes_diameter(b, j) ? v / 2 : v;
}

// The checks of G51/G52; false with `error` set when the block is refused.
bool Planner::check_diameter(const nc::Block& b, Command& c, Command& error) {
  const bool switched = b.modal.diameter != diameter_on_;
  diameter_on_ = b.modal.diameter;
  if (switched) {
    const PlaneAxes pa = plane_axes(b.modal.plane);
    int in_plane = -1, count = 0;
    for (int k : {pa.first, pa.second}) {
      const int j = axis_named(kMainAxisNames[k]);
      if (j >= 0 && ((face_axes_ >> j) & 1u)) {
        in_plane = j;
        ++count;
      }
    }
    if (count != 1) {
      error = error_command(ErrorId::KernelNoFaceAxisInPlane,
                            fmt::format("G{}: {} face-turning axes in the plane G{}; exactly one is needed",
                                        b.modal.diameter ? 51 : 52, count, static_cast<int>(b.modal.plane)),
                            b.file_id, b.line);
      return false;
    }
    const std::uint32_t bit = 1u << in_plane;
    if (b.modal.diameter && !((diameter_abs_axes_ | diameter_rel_axes_) & bit))
      (void)c.warnings.push_back(
          {ErrorId::KernelDiameterNotConfigured,
           store_.add_message(fmt::format("G51: {} has neither kenngr.durchm_prog_abs nor durchm_prog_rel; "
                                          "its positions stay radii",
                                          channel_.axes[static_cast<std::size_t>(in_plane)].name))});
  }
  if (!b.modal.diameter) return true;
  if (b.hash && (std::holds_alternative<nc::PSet>(*b.hash) || std::holds_alternative<nc::PReset>(*b.hash))) {
    error = error_command(ErrorId::KernelPresetInDiameter, "#PSET/#PRESET while G51 is active", b.file_id,
                          b.line);
    return false;
  }
  if (!b.modal.absolute) return true;
  for (std::size_t j = 0; j < n_axes_; ++j)
    if (b.axes[j] && *b.axes[j] < 0 && takes_diameter(b, j)) {
      error = error_command(ErrorId::KernelNegativeDiameter,
                            fmt::format("{}{:g} under G51: a diameter cannot be negative",
                                        channel_.axes[j].name, *b.axes[j]),
                            b.file_id, b.line);
      return false;
    }
  return true;
}

}  // namespace nck::prep
