// G130...G134, G233 on the path axes (dyn_weights.hpp): the block's
// weightings checked against each axis's limits, then the factors in force.
#include "nck/prep/units/dyn_weights.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace nck::prep {
namespace {

// The ramp times are list values in µs (UNS32): no weighting may go beyond.
constexpr double kLongestRampS = 4294.967295;
// Factors are compared with a relative margin so that 100 % of a limit
// that equals the configured value is never refused for rounding.
constexpr double kEps = 1e-12;

motion::RampTimes scaled(const motion::RampTimes& t, double f) {
  return {t.acc_up_s * f, t.acc_down_s * f, t.dec_up_s * f, t.dec_down_s * f};
}

// A ramp time weighted by f: shorter than floor_s only when shortened, and
// never longer than the list allows.
bool ramp_ok(double tr_s, double f, double floor_s) {
  const double w = tr_s * f;
  return (f >= 1.0 || w >= floor_s * (1 - kEps)) && w <= kLongestRampS;
}

std::string pct(double f) { return fmt::format("{:g} %", f * 100); }

}  // namespace

void DynWeights::restore() {
  acc_.fill(1.0);
  ramp_.fill(1.0);
  geom_ = rapid_ramp_ = 1.0;
  active_ = false;
}

void DynWeights::update_active() {
  active_ = geom_ != 1.0 || rapid_ramp_ != 1.0;
  for (std::size_t j = 0; j < n_axes_; ++j) active_ = active_ || acc_[j] != 1.0 || ramp_[j] != 1.0;
}

PlanResult DynWeights::apply(const nc::Block& b, const AxisTable& axes, const config::ChannelConfig& channel) {
  using nc::GCode;
  using nc::GroupWeight;
  const nc::GCodeSet& g = b.g_nonmodal;
  if (b.slope_default) restore();
  DynWeights next = *this;  // all of the block's weightings, or none
  auto per_axis = [&](AxisArray& f) {
    f.fill(1.0);  // the axes the block does not name go back to 100 %
    for (std::size_t j = 0; j < n_axes_; ++j)
      if (b.axes[j]) f[j] = *b.axes[j] / 100.0;
  };
  if (g.has(GCode::g130) && b.has_axis_words()) per_axis(next.acc_);
  if (g.has(GCode::g131)) next.acc_.fill(b.group_weight(GroupWeight::g131) / 100.0);
  if (g.has(GCode::g132)) per_axis(next.ramp_);
  if (g.has(GCode::g133)) next.ramp_.fill(b.group_weight(GroupWeight::g133) / 100.0);
  if (g.has(GCode::g134)) next.geom_ = b.group_weight(GroupWeight::g134) / 100.0;
  if (g.has(GCode::g233)) next.rapid_ramp_ = b.group_weight(GroupWeight::g233) / 100.0;
  for (std::size_t j = 0; j < n_axes_; ++j) {
    const motion::AxisDynamics& feed = axes.dynamics(false)[j];
    const motion::AxisDynamics& rapid = axes.dynamics(true)[j];
    const WeightLimits& lim = axes.weight_limits(j);
    const std::string& name = j < channel.axes.size() ? channel.axes[j].name : std::string("?");
    const double a_w = std::max(feed.a_acc_mm_s2, feed.a_dec_mm_s2) * next.acc_[j];
    if (a_w > lim.a_w_max_mm_s2 * (1 + kEps))
      return block_error(ErrorId::KernelWeightedAcceleration, b,
                         fmt::format("axis {}: {} of its feed acceleration is {:g}, above a_w_max {:g}", name,
                                     pct(next.acc_[j]), a_w, lim.a_w_max_mm_s2));
    const motion::RampTimes& t = feed.tr;
    for (double tr : {t.acc_up_s, t.acc_down_s, t.dec_up_s, t.dec_down_s})
      if (!ramp_ok(tr, next.ramp_[j], lim.tr_w_min_s))
        return block_error(ErrorId::KernelWeightedRampTime, b,
                           fmt::format("axis {}: {} of its feed ramp time {:g} s leaves {:g} ... {:g} s", name,
                                       pct(next.ramp_[j]), tr, lim.tr_w_min_s, kLongestRampS));
    if (!ramp_ok(feed.tr_geom_s, next.geom_, lim.tr_min_s))
      return block_error(ErrorId::KernelWeightedRampTime, b,
                         fmt::format("axis {}: G134 {} of tr_geom {:g} s is below tr_min {:g} s", name, pct(next.geom_),
                                     feed.tr_geom_s, lim.tr_min_s));
    if (!ramp_ok(rapid.tr.acc_up_s, next.rapid_ramp_, lim.tr_min_s))
      return block_error(ErrorId::KernelWeightedRampTime, b,
                         fmt::format("axis {}: G233 {} of tr_grenz {:g} s is below tr_min {:g} s", name,
                                     pct(next.rapid_ramp_), rapid.tr.acc_up_s, lim.tr_min_s));
  }
  *this = next;
  update_active();
  return {};
}

void DynWeights::weigh(AxisDynamicsArray& dyn, bool rapid) const {
  for (std::size_t j = 0; j < n_axes_; ++j) {
    motion::AxisDynamics& d = dyn[j];
    if (rapid) {
      d.tr = scaled(d.tr, rapid_ramp_);
      continue;
    }
    d.a_acc_mm_s2 *= acc_[j];
    d.a_dec_mm_s2 *= acc_[j];
    d.tr = scaled(d.tr, ramp_[j]);
    d.tr_geom_s *= geom_;
  }
}

WeightScale DynWeights::scale() const {
  if (!active_) return {};
  WeightScale s{1e300, 0.0, 0.0, geom_};
  for (std::size_t j = 0; j < n_axes_; ++j) {
    s.acc_min = std::min(s.acc_min, acc_[j]);
    s.acc_max = std::max(s.acc_max, acc_[j]);
    s.ramp_max = std::max(s.ramp_max, ramp_[j]);
  }
  if (n_axes_ == 0) s = WeightScale{1.0, 1.0, 1.0, geom_};
  return s;
}

}  // namespace nck::prep
