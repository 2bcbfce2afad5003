// #DIST CTRL in preparation; see nck/distctrl/prep_unit.hpp.
#include "nck/distctrl/prep_unit.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "nck/prep/units/axis_table.hpp"

namespace nck::prep {
namespace {

std::int8_t filter_kind(const std::string& name) {
  static constexpr std::pair<std::string_view, distctrl::FilterKind> kNames[] = {
      {"MOVING_AVERAGE", distctrl::FilterKind::moving_average}, {"LOWPASS", distctrl::FilterKind::lowpass},
      {"KALMAN_MA", distctrl::FilterKind::kalman_ma},           {"EXPO_MEAN", distctrl::FilterKind::expo_mean},
      {"KALMAN_EXPO", distctrl::FilterKind::kalman_expo}};
  for (auto [n, k] : kNames)
    if (name == n) return static_cast<std::int8_t>(k);
  return -1;
}

// "" when every override lies in its parameter's range, else what is wrong.
std::string override_range(const nc::DistCtrl& d) {
  auto out = [](const char* key, double v, double lo, double hi, bool lo_open) {
    const bool bad = v > hi || (lo_open ? v <= lo : v < lo);
    return bad ? fmt::format("{}={} is outside {}{} .. {}", key, v, lo_open ? "> " : "", lo, hi) : std::string();
  };
  std::string why;
  auto check = [&](const char* key, const auto& v, double lo, double hi, bool lo_open = false) {
    if (v && why.empty()) why = out(key, static_cast<double>(*v), lo, hi, lo_open);
  };
  check("KP", d.kp, 0.0, 2.0, true);                    // P-CHAN-00821
  check("I_TN", d.i_tn, 0.0, 50.0);                     // P-CHAN-00822
  check("D_TV", d.d_tv, 0.0, 2.0);                      // P-CHAN-00823
  check("N_CYCLES", d.n_cycles, 0.0, 99.0);             // P-CHAN-00800
  check("ORDER", d.order, 0.0, 6.0);                    // P-CHAN-00816
  check("KALMAN_SIGMA", d.kalman_sigma, 1.0, 10000.0);  // P-CHAN-00826
  check("SMOOTH_FACT", d.smooth_fact, 0.0, 1.0, true);  // P-CHAN-00827
  return why;
}

}  // namespace

PlanResult DistUnit::plan_source(const nc::Block& b, const nc::DistCtrl& d, distctrl::DistChange& change) {
  if (d.sensor_source) {
    using Source = distctrl::DistChange::Source;
    std::optional<Source> source;
    if (*d.sensor_source == "VARIABLE") source = Source::variable;
    else if (*d.sensor_source == "SIMULATION" || *d.sensor_source == "SENSOR") source = Source::machine;
    if (!source)
      return block_error(ErrorId::DistCtrlSourceNotAllowed, b,
                         fmt::format("SENSOR_SOURCE={} is not available for 3D distance control: "
                                     "SIMULATION or VARIABLE", *d.sensor_source));
    if (on_ && *source != source_)
      return block_error(ErrorId::DistCtrlSourceChange, b,
                         fmt::format("SENSOR_SOURCE={} while distance control is on", *d.sensor_source));
    source_ = *source;
    change.source = source;
  }
  if (d.sensor_var) {
    if (d.sensor_var->empty() || d.sensor_var->size() >= change.variable.size())
      return block_error(ErrorId::DistCtrlBadVariable, b,
                         "SENSOR_VAR must name a channel variable (up to 31 characters)");
    std::copy(d.sensor_var->begin(), d.sensor_var->end(), change.variable.begin());
    change.source = source_;
  }
  return {};
}

PlanResult DistUnit::plan(const nc::Block& b, PlannedCommand& c, const PlanContext& ctx) {
  const auto* d = b.hash ? std::get_if<nc::DistCtrl>(&*b.hash) : nullptr;
  if (!d) return {};
  if (std::string why = override_range(*d); !why.empty()) return block_error(ErrorId::DistCtrlOverride, b, why);
  distctrl::DistChange change;
  if (auto r = plan_source(b, *d, change); !r) return r;
  distctrl::Switch& w = change.sw;
  switch (d->op) {
    case nc::DistCtrlOp::on: w.op = distctrl::Op::on; break;
    case nc::DistCtrlOp::freeze: w.op = distctrl::Op::freeze; break;
    case nc::DistCtrlOp::off: w.op = distctrl::Op::off; break;
    case nc::DistCtrlOp::settings: w.op = distctrl::Op::none; break;
  }
  if (w.op == distctrl::Op::on && source_ == distctrl::DistChange::Source::variable && !d->sensor_var && !var_known_)
    return block_error(ErrorId::DistCtrlBadVariable, b, "SENSOR_SOURCE=VARIABLE needs SENSOR_VAR=<variable>");
  if (d->sensor_var) var_known_ = true;
  w.const_dist = d->const_dist;
  w.no_move = d->no_move;
  if (d->set_pos_mm) w.set_pos_mm = *d->set_pos_mm;
  if (d->set_dist_mm) w.set_dist_mm = *d->set_dist_mm;
  if (d->kp) w.kp = *d->kp;
  if (d->i_tn) w.i_tn_s = *d->i_tn;
  if (d->d_tv) w.d_tv_s = *d->d_tv;
  if (d->fg_f0) w.f0_hz = *d->fg_f0;
  if (d->smooth_fact) w.smoothing = *d->smooth_fact;
  if (d->kalman_sigma) w.kalman_sigma = *d->kalman_sigma;
  if (d->n_cycles) w.n_cycles = static_cast<std::int16_t>(*d->n_cycles);
  if (d->order) w.order = static_cast<std::int16_t>(*d->order);
  if (d->filter_type) w.filter = filter_kind(*d->filter_type);
  if (w.op == distctrl::Op::on || w.op == distctrl::Op::freeze) on_ = programmed_ = true;
  if (w.op == distctrl::Op::off) on_ = false;
  // The tool axis of the working plane carries the offset (Z for G17).
  const int tool = plane_axes(b.modal.plane).tool;
  change.axis = static_cast<std::int8_t>(tool < static_cast<int>(ctx.n_axes) ? tool : -1);
  if (ctx.channel.dist_ctrl.check_sw_limit_switch) {
    const auto j = static_cast<std::size_t>(tool);
    change.sw_limits_mm = change.axis >= 0 ? std::array<double, 2>{ctx.axes.sw_limit_neg_mm(j), ctx.axes.sw_limit_pos_mm(j)}
                                           : std::array<double, 2>{0, 0};
  }
  if (w.any()) c.attach(change);
  return {};
}

}  // namespace nck::prep
