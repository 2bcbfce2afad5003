// G100 measuring runs and the G101/G102 measuring offset.
#include <algorithm>
#include <fmt/format.h>

#include "nck/prep/planner.hpp"

namespace nck::prep {

// G100: a linear move at F that stops where the probe switches.
Command Planner::plan_measuring_run(const nc::Block& b, Command c) {
  nc::Block run = b;
  run.modal.motion = nc::Motion::linear;
  c = plan_motion(run, c);
  if (c.kind != CommandKind::motion) return c;
  c.measure = true;
  c.probe_axis = probe_axis_;
  c.probe_pos_mm = probe_pos_mm_;
  measure_target_pcs_ = pcs_;
  return c;
}

std::vector<std::pair<std::string, double>> Planner::take_measurement(const kernel::MeasureResult& r) {
  std::vector<std::pair<std::string, double>> vars;
  mcs_ = r.mcs;
  pcs_ = frames_.to_pcs(mcs_);
  measured_ = Measured{true, r.triggered, pcs_, measure_target_pcs_};
  for (std::size_t j = 0; j < n_axes_; ++j) {
    const std::string& ax = channel_.axes[j].name;
    vars.emplace_back("V.A.MERF." + ax, r.triggered ? 1.0 : 0.0);
    if (!r.triggered) continue;
    vars.emplace_back("V.A.MESS." + ax, pcs_[j]);
    vars.emplace_back("V.A.MOFFS." + ax, pcs_[j] - measure_target_pcs_[j]);
  }
  return vars;
}

// G101 X<factor>..: (measured - target) * factor as an offset; G102 [X..]
// removes it. Both act at the axis's next absolute position.
bool Planner::apply_measure_offset(const nc::Block& b, Command& c, Command& error) {
  const bool g101 = b.g_nonmodal.has(nc::GCode::g101);
  const bool g102 = b.g_nonmodal.has(nc::GCode::g102);
  if (!g101 && !g102) return true;
  std::optional<Diagnostic> fail;
  if (g102 && !b.has_axis_words()) fail = frames_.measure_clear(std::nullopt, b);
  for (std::size_t j = 0; j < n_axes_ && !fail; ++j) {
    if (!b.axes[j]) continue;
    if (g102) {
      fail = frames_.measure_clear(j, b);
    } else {
      const bool measured = measured_.any && measured_.triggered;
      fail = frames_.measure_apply(j, *b.axes[j],
                                   measured ? std::optional(measured_.measured_pcs[j]) : std::nullopt,
                                   measured_.target_pcs[j], b);
    }
  }
  if (fail) {
    error = error_command(fail->id, fail->message, b.file_id, b.line);
    return false;
  }
  (void)c.offset_events.push_back(store_.add_offset({"measure", frames_.values_of(frames::OffsetKind::measure, true)}));
  return true;
}

}  // namespace nck::prep
