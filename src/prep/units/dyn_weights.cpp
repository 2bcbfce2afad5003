// G130...G134, G233 on the path axes (dyn_weights.hpp): the factors in
// force, each weighted value limited to its range, and a warning for each
// kind of limit a block's weighting runs into.
#include "nck/prep/units/dyn_weights.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace nck::prep {
namespace {

// The ramp times are list values in µs (UNS32): no weighting may go beyond.
constexpr double kLongestRampS = 4294.967295;
// A weighted value counts as beyond a limit by a relative margin, so that
// 100 % of a limit that equals the configured value never warns for rounding.
constexpr double kEps = 1e-12;

// v weighted by f within lo ... hi. A weighting never takes a value past
// its configured one the wrong way (a list value outside the range stays).
double limited(double v, double f, double lo, double hi) {
  return std::clamp(v * f, std::min(v, lo), std::max(v, hi));
}

motion::RampTimes limited(const motion::RampTimes& t, double f, double lo) {
  auto l = [&](double v) { return limited(v, f, lo, kLongestRampS); };
  return {l(t.acc_up_s), l(t.acc_down_s), l(t.dec_up_s), l(t.dec_down_s)};
}

std::string pct(double f) { return fmt::format("{:g} %", f * 100); }

// One end of a weighted value's range and the warning for going past it.
struct Bound {
  double value;
  std::string_view name;
  ErrorId id;
};

// A configured value (name, unit) weighted by f, to stay within lo ... hi.
struct Weighted {
  std::string_view name;
  double v, f;
  Bound lo, hi;
  std::string_view unit;
};

// The limited values of one axis: one text per kind (warning ID).
class AxisFindings {
 public:
  void check(const Weighted& w) {
    const double raw = w.v * w.f, used = limited(w.v, w.f, w.lo.value, w.hi.value);
    const bool below = raw < w.lo.value * (1 - kEps);
    if (used == raw || (!below && raw <= w.hi.value * (1 + kEps))) return;
    const Bound& b = below ? w.lo : w.hi;
    add(b.id, fmt::format("{} {:g}{} at {} is {:g}{}, {} {} {:g}{}: {:g}{} used", w.name, w.v, w.unit, pct(w.f), raw,
                          w.unit, below ? "below" : "above", b.name, b.value, w.unit, used, w.unit));
  }
  void append_to(std::vector<Diagnostic>& out, std::string_view axis, const nc::Block& b) const {
    for (const auto& [id, text] : found_)
      out.push_back(make_diagnostic(id, SourceLoc{{}, b.line, 0}, fmt::format("axis {}: {}", axis, text)));
  }

 private:
  void add(ErrorId id, std::string text) {
    for (auto& [known, all] : found_)
      if (known == id) {
        all += "; " + text;
        return;
      }
    found_.emplace_back(id, std::move(text));
  }
  std::vector<std::pair<ErrorId, std::string>> found_;
};

Bound longest(ErrorId id) { return {kLongestRampS, "the longest list value", id}; }

// G130/G131: a_beschl and a_brems each up to a_w_max (no floor: factors are > 0).
void check_acc(AxisFindings& out, const motion::AxisDynamics& d, double f, const WeightLimits& lim) {
  const Bound none{0, "", ErrorId::KernelWeightAccLimited};
  const Bound hi{lim.a_w_max_mm_s2, "a_w_max", ErrorId::KernelWeightAccLimited};
  out.check({"a_beschl", d.a_acc_mm_s2, f, none, hi, ""});
  out.check({"a_brems", d.a_dec_mm_s2, f, none, hi, ""});
}

// G132/G133: the four feed ramp times (P-AXIS-00195...00198) tr_w_min ... longest.
void check_ramps(AxisFindings& out, const motion::RampTimes& t, double f, const WeightLimits& lim) {
  const Bound shortest{lim.tr_w_min_s, "tr_w_min", ErrorId::KernelWeightRampBelowMin};
  const Bound shortest_dec_down{lim.tr_w_min_s, "tr_w_min", ErrorId::KernelWeightDecDownBelowMin};
  const Bound hi = longest(ErrorId::KernelWeightRampAboveMax);
  out.check({"tr_beschl_ab", t.acc_down_s, f, shortest, hi, " s"});
  out.check({"tr_beschl_zu", t.acc_up_s, f, shortest, hi, " s"});
  out.check({"tr_brems_ab", t.dec_down_s, f, shortest_dec_down, hi, " s"});
  out.check({"tr_brems_zu", t.dec_up_s, f, shortest, hi, " s"});
}

// G134 (tr_geom) and G233 (tr_grenz): tr_min ... the longest list value.
Weighted min_ramp(std::string_view name, double tr, double f, const WeightLimits& lim, ErrorId below, ErrorId above) {
  return {name, tr, f, {lim.tr_min_s, "tr_min", below}, longest(above), " s"};
}

}  // namespace

DynWeights::DynWeights(const AxisTable& axes) : n_axes_(axes.count()) {
  for (std::size_t j = 0; j < n_axes_; ++j) {
    limits_[j] = axes.weight_limits(j);
    a_along_[j] = std::max(axes.feed()[j].a_acc_mm_s2, axes.feed()[j].a_dec_mm_s2);
  }
  restore();
}

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

std::vector<Diagnostic> DynWeights::apply(const nc::Block& b, const AxisTable& axes,
                                          const config::ChannelConfig& channel) {
  using nc::GCode;
  using nc::GroupWeight;
  const nc::GCodeSet& g = b.g_nonmodal;
  if (b.slope_default) restore();
  auto per_axis = [&](AxisArray& f) {
    f.fill(1.0);  // the axes the block does not name go back to 100 %
    for (std::size_t j = 0; j < n_axes_; ++j)
      if (b.axes[j]) f[j] = *b.axes[j] / 100.0;
  };
  if (g.has(GCode::g130) && b.has_axis_words()) per_axis(acc_);
  if (g.has(GCode::g131)) acc_.fill(b.group_weight(GroupWeight::g131) / 100.0);
  if (g.has(GCode::g132)) per_axis(ramp_);
  if (g.has(GCode::g133)) ramp_.fill(b.group_weight(GroupWeight::g133) / 100.0);
  if (g.has(GCode::g134)) geom_ = b.group_weight(GroupWeight::g134) / 100.0;
  if (g.has(GCode::g233)) rapid_ramp_ = b.group_weight(GroupWeight::g233) / 100.0;
  update_active();
  return limited_values(b, axes, channel);
}

std::vector<Diagnostic> DynWeights::limited_values(const nc::Block& b, const AxisTable& axes,
                                                   const config::ChannelConfig& channel) const {
  using nc::GCode;
  const nc::GCodeSet& g = b.g_nonmodal;
  const bool acc = g.has(GCode::g131) || (g.has(GCode::g130) && b.has_axis_words());
  const bool ramps = g.has(GCode::g132) || g.has(GCode::g133);
  std::vector<Diagnostic> out;
  for (std::size_t j = 0; j < n_axes_; ++j) {
    const motion::AxisDynamics& feed = axes.dynamics(false)[j];
    const WeightLimits& lim = limits_[j];
    AxisFindings found;
    if (acc) check_acc(found, feed, acc_[j], lim);
    if (ramps) check_ramps(found, feed.tr, ramp_[j], lim);
    if (g.has(GCode::g134))
      found.check(min_ramp("tr_geom", feed.tr_geom_s, geom_, lim, ErrorId::KernelWeightGeomRampLimited,
                           ErrorId::KernelWeightGeomRampLimited));
    if (g.has(GCode::g233))
      found.check(min_ramp("tr_grenz", axes.dynamics(true)[j].tr.acc_up_s, rapid_ramp_, lim,
                           ErrorId::KernelWeightRapidRampBelowMin, ErrorId::KernelWeightRapidRampAboveMax));
    found.append_to(out, j < channel.axes.size() ? channel.axes[j].name : std::string("?"), b);
  }
  return out;
}

void DynWeights::weigh(AxisDynamicsArray& dyn, bool rapid) const {
  for (std::size_t j = 0; j < n_axes_; ++j) {
    motion::AxisDynamics& d = dyn[j];
    const WeightLimits& lim = limits_[j];
    if (rapid) {
      d.tr = limited(d.tr, rapid_ramp_, lim.tr_min_s);
      continue;
    }
    d.a_acc_mm_s2 = limited(d.a_acc_mm_s2, acc_[j], 0, lim.a_w_max_mm_s2);
    d.a_dec_mm_s2 = limited(d.a_dec_mm_s2, acc_[j], 0, lim.a_w_max_mm_s2);
    d.tr = limited(d.tr, ramp_[j], lim.tr_w_min_s);
    d.tr_geom_s = limited(d.tr_geom_s, geom_, lim.tr_min_s, kLongestRampS);
  }
}

double DynWeights::acc_used(std::size_t j) const {
  const double v = a_along_[j];
  return v > 0 ? limited(v, acc_[j], 0, limits_[j].a_w_max_mm_s2) / v : acc_[j];
}

WeightScale DynWeights::scale() const {
  if (!active_) return {};
  WeightScale s{1e300, 0.0, 0.0, geom_};
  for (std::size_t j = 0; j < n_axes_; ++j) {
    s.acc_min = std::min(s.acc_min, acc_used(j));
    s.acc_max = std::max(s.acc_max, acc_used(j));
    s.ramp_max = std::max(s.ramp_max, ramp_[j]);
  }
  if (n_axes_ == 0) s = WeightScale{1.0, 1.0, 1.0, geom_};
  return s;
}

}  // namespace nck::prep
