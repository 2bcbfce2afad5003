// G100 measuring runs and the G101/G102 measuring offset; see measure_unit.hpp.
#include "nck/prep/units/measure_unit.hpp"

#include <optional>
#include <utility>

namespace nck::prep {

void MeasureUnit::start_run(PlannedCommand& c, const PlanContext& ctx) {
  c.measure = true;
  target_pcs_ = ctx.planned.pcs;
}

std::vector<std::pair<std::string, double>> MeasureUnit::take_measurement(const kernel::MeasureResult& r,
                                                                          PlanContext& ctx) {
  std::vector<std::pair<std::string, double>> vars;
  ctx.planned.mcs = r.mcs;
  ctx.planned.reread(ctx.frames);
  const motion::AxisVector& pcs = ctx.planned.pcs;
  any_ = true;
  triggered_ = r.triggered;
  measured_pcs_ = pcs;
  run_target_pcs_ = target_pcs_;
  for (std::size_t j = 0; j < ctx.n_axes; ++j) {
    const std::string& ax = ctx.channel.axes[j].name;
    vars.emplace_back("V.A.MERF." + ax, r.triggered ? 1.0 : 0.0);
    if (!r.triggered) continue;
    vars.emplace_back("V.A.MESS." + ax, pcs[j]);
    vars.emplace_back("V.A.MOFFS." + ax, pcs[j] - target_pcs_[j]);
  }
  return vars;
}

PlanResult MeasureUnit::apply_offset(const nc::Block& b, PlannedCommand& c, PlanContext& ctx) const {
  const bool g101 = b.g_nonmodal.has(nc::GCode::g101);
  const bool g102 = b.g_nonmodal.has(nc::GCode::g102);
  if (!g101 && !g102) return {};
  PlanResult done;
  if (g102 && !b.has_axis_words()) done = ctx.frames.measure_clear(std::nullopt, b);
  for (std::size_t j = 0; j < ctx.n_axes && done; ++j) {
    if (!b.axes[j]) continue;
    if (g102) {
      done = ctx.frames.measure_clear(j, b);
    } else {
      const bool measured = any_ && triggered_;
      done = ctx.frames.measure_apply(j, *b.axes[j], measured ? std::optional(measured_pcs_[j]) : std::nullopt,
                                      run_target_pcs_[j], b);
    }
  }
  if (!done) return done;
  c.attach(frames::OffsetEvent{ctx.store.add_offset({"measure", ctx.frames.values_of(frames::OffsetKind::measure, true)})});
  return {};
}

}  // namespace nck::prep
