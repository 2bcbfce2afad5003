#include "nck/motion/limits.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace nck::motion {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Direction components below this do not limit (an axis that hardly moves).
constexpr double kMinShare = 1e-12;

void limit_by_share(PathLimits& out, const AxisDynamics& ax, double share) noexcept {
  if (!(share > kMinShare)) return;
  out.tr = longest(out.tr, ax.tr);
  out.v_max_mm_s = std::min(out.v_max_mm_s, ax.v_max_mm_s / share);
  out.a_acc_mm_s2 = std::min(out.a_acc_mm_s2, ax.a_acc_mm_s2 / share);
  out.a_dec_mm_s2 = std::min(out.a_dec_mm_s2, ax.a_dec_mm_s2 / share);
}


// Ramp times shortened by the share an acceleration keeps (at most 1).
RampTimes scaled(const RampTimes& t, double acc_share, double dec_share) noexcept {
  acc_share = std::clamp(acc_share, 0.0, 1.0);
  dec_share = std::clamp(dec_share, 0.0, 1.0);
  return RampTimes{t.acc_up_s * acc_share, t.acc_down_s * acc_share, t.dec_up_s * dec_share, t.dec_down_s * dec_share};
}

void add_arc_plane(PathLimits& out, const Segment& seg, std::span<const AxisDynamics> axes,
                   SlopeProfile slope) noexcept {
  const std::size_t a = seg.plane_a(), b = seg.plane_b();
  if (a >= axes.size() || b >= axes.size()) return;
  const AxisDynamics& da = axes[a];
  const AxisDynamics& db = axes[b];
  // Share of the path velocity that runs in the plane (1 for a plain arc).
  const double plane_share = seg.plane_arc_length() / seg.length();
  if (!(plane_share > kMinShare)) return;
  const double v_plane = std::min(da.v_max_mm_s, db.v_max_mm_s);
  const double acc_plane = std::min(da.a_acc_mm_s2, db.a_acc_mm_s2);
  const double dec_plane = std::min(da.a_dec_mm_s2, db.a_dec_mm_s2);
  // Centripetal acceleration acts whether the path speeds up or slows down.
  const double any_plane = std::min(acc_plane, dec_plane);
  const double split = std::numbers::sqrt2;
  const double r = std::min(seg.radius_start(), seg.radius_end());
  const double v_centripetal = std::sqrt(std::max(any_plane, 0.0) * r / split);
  double v_arc = std::min(v_plane, v_centripetal);
  double acc_t = acc_plane / split, dec_t = dec_plane / split;
  out.tr = longest(out.tr, longest(da.tr, db.tr));
  if (jerk_limited(slope)) {
    // On a circle the jerk is (j_t - v^3/r^2) along the path plus
    // 3 v a_t / r across it; a plane axis takes at most its length. With
    // the path's own jerk j_t at most J / split (J = a/tr) and each turning
    // term at most g, that length stays within J where
    // (J / split + g)^2 + g^2 = J^2: g = (sqrt6 - sqrt2) / 4 J, 0.259 J
    // (summing the three instead left each 0.146 J).
    const RampTimes& t = out.tr;
    const double tr = std::max({t.acc_up_s, t.acc_down_s, t.dec_up_s, t.dec_down_s, da.tr_geom_s, db.tr_geom_s});
    constexpr double kTurnShare = (std::numbers::sqrt3 * std::numbers::sqrt2 - std::numbers::sqrt2) / 4.0;
    const double j_geom = tr > 0 ? kTurnShare * any_plane / tr : kInf;
    v_arc = std::min(v_arc, std::cbrt(j_geom * r * r));
    const double a_t = v_arc > 0 ? j_geom * r / (3.0 * v_arc) : kInf;
    acc_t = std::min(acc_t, a_t);
    dec_t = std::min(dec_t, a_t);
  }
  // The path's accelerations without the turn's hold on them (the axes' own).
  const double acc_free = std::min(out.a_acc_mm_s2, acc_plane / split / plane_share);
  const double dec_free = std::min(out.a_dec_mm_s2, dec_plane / split / plane_share);
  out.v_max_mm_s = std::min(out.v_max_mm_s, v_arc / plane_share);
  out.a_acc_mm_s2 = std::min(out.a_acc_mm_s2, acc_t / plane_share);
  out.a_dec_mm_s2 = std::min(out.a_dec_mm_s2, dec_t / plane_share);
  // The path's own jerk keeps what the axes allow (a / tr): an acceleration
  // the turn holds down ramps in a shorter time, not over the whole ramp
  // time (a small arc took ten times as long). Where an axis's own limit
  // binds (a helix's slow axis), nothing changes.
  if (jerk_limited(slope)) out.tr = scaled(out.tr, out.a_acc_mm_s2 / acc_free, out.a_dec_mm_s2 / dec_free);
}

// A cubic span (a smoothed chord): its tangent turns within the span and
// from span to span without a step, so its curvature kappa(s) limits the
// speed as an arc's radius does (v^2 kappa across the path), and under a
// jerk-limited slope the turning acceleration's change, v^3 sqrt(kappa'^2 +
// kappa^4), and speeding up while turning, 3 v a_t kappa, stay within the
// share of a/tr that an arc gets. kappa from the unit tangent's change
// between samples.
void add_cubic_curve(PathLimits& out, const Segment& seg, std::span<const AxisDynamics> axes, SlopeProfile slope,
                     double v_cap_mm_s) noexcept {
  constexpr int kSamples = 16;
  const double len = seg.length(), step = len / kSamples;
  double acc = kInf, dec = kInf, tr_geom = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t i = seg.cubic_axis(k);
    if (i >= axes.size()) return;
    acc = std::min(acc, axes[i].a_acc_mm_s2);
    dec = std::min(dec, axes[i].a_dec_mm_s2);
    tr_geom = std::max(tr_geom, axes[i].tr_geom_s);
  }
  std::array<double, kSamples + 1> kappa{};
  AxisVector t0{}, t1{};
  auto tangent_length = [&](double s, AxisVector& t) {
    seg.tangent_at(s, t);
    return seg.cubic_norm([&](std::size_t k) { return t[seg.cubic_axis(k)]; });
  };
  for (int n = 0; n <= kSamples; ++n) {
    const double s = n * step, h = 0.25 * step;
    const double a = std::max(s - h, 0.0), b = std::min(s + h, len);
    const double speed0 = tangent_length(a, t0), speed1 = tangent_length(b, t1);
    const double turn = seg.cubic_norm([&](std::size_t k) {
      const std::size_t i = seg.cubic_axis(k);
      return t1[i] / speed1 - t0[i] / speed0;
    });
    kappa[static_cast<std::size_t>(n)] = turn / (0.5 * (speed0 + speed1) * (b - a));
  }
  double kappa_max = 0, jerk_shape = 0;  // max kappa, max sqrt(kappa'^2 + kappa^4)
  for (std::size_t n = 0; n <= kSamples; ++n) {
    const double k = kappa[n];
    const double slope_k = n == 0 ? (kappa[1] - k) / step
                         : n == kSamples ? (k - kappa[n - 1]) / step
                                         : (kappa[n + 1] - kappa[n - 1]) / (2 * step);
    kappa_max = std::max(kappa_max, k);
    jerk_shape = std::max(jerk_shape, std::sqrt(slope_k * slope_k + k * k * k * k));
  }
  const double any = std::min(acc, dec), split = std::numbers::sqrt2;
  double v = std::min(kappa_max > 0 ? std::sqrt(any / split / kappa_max) : kInf, v_cap_mm_s);
  double acc_t = acc / split, dec_t = dec / split;
  if (jerk_limited(slope)) {
    const RampTimes& t = out.tr;
    const double tr = std::max({t.acc_up_s, t.acc_down_s, t.dec_up_s, t.dec_down_s, tr_geom});
    const double j_geom = tr > 0 ? (1.0 - 1.0 / split) / 2.0 * any / tr : kInf;
    if (jerk_shape > 0) v = std::min(v, std::cbrt(j_geom / jerk_shape));
    const double a_t = v > 0 && kappa_max > 0 ? j_geom / (3.0 * v * kappa_max) : kInf;
    acc_t = std::min(acc_t, a_t);
    dec_t = std::min(dec_t, a_t);
  }
  out.v_max_mm_s = std::min(out.v_max_mm_s, v);
  out.a_acc_mm_s2 = std::min(out.a_acc_mm_s2, acc_t);
  out.a_dec_mm_s2 = std::min(out.a_dec_mm_s2, dec_t);
}

}  // namespace

JerkLimits jerk_limits(const PathLimits& l) noexcept {
  RampTimes t = l.tr;
  if (l.slope == SlopeProfile::hsc) {
    // HSC: the longest of the (weighted) ramp times is always in force
    // (TF5200 P-CHAN-00071), in every phase.
    const double longest_s = std::max({t.acc_up_s, t.acc_down_s, t.dec_up_s, t.dec_down_s});
    t = RampTimes{longest_s, longest_s, longest_s, longest_s};
  }
  return JerkLimits{l.a_acc_mm_s2, l.a_dec_mm_s2, t.acc_up_s, t.acc_down_s,
                    t.dec_up_s,    t.dec_down_s,  l.slope == SlopeProfile::sin2};
}

RampTimes longest(const RampTimes& a, const RampTimes& b) noexcept {
  return RampTimes{std::max(a.acc_up_s, b.acc_up_s), std::max(a.acc_down_s, b.acc_down_s),
                   std::max(a.dec_up_s, b.dec_up_s), std::max(a.dec_down_s, b.dec_down_s)};
}

bool valid(const PathLimits& l) noexcept {
  auto ok = [](double x) { return std::isfinite(x) && x > 0.0; };
  return ok(l.v_max_mm_s) && ok(l.a_acc_mm_s2) && ok(l.a_dec_mm_s2);
}

PathLimits any_direction_limits(std::span<const AxisDynamics> axes) noexcept {
  PathLimits out{kInf, kInf, kInf};
  for (const AxisDynamics& a : axes) limit_by_share(out, a, 1.0);
  if (!std::isfinite(out.v_max_mm_s)) out = PathLimits{};
  return out;
}

PathLimits path_limits(const Segment& seg, std::span<const AxisDynamics> axes, SlopeProfile slope,
                       double v_cap_mm_s) noexcept {
  const double len = seg.length();
  // Length 0: nothing moves; the smallest axis limits keep the result usable.
  if (!(len > 0.0)) return any_direction_limits(axes.first(std::min(seg.axis_count(), axes.size())));
  PathLimits out{kInf, kInf, kInf};
  out.slope = slope;
  const bool arc = seg.kind() == SegmentKind::arc;
  const std::size_t n = std::min(seg.axis_count(), axes.size());
  const AxisVector& p0 = seg.start_point();
  const AxisVector& p1 = seg.end_point();
  if (seg.kind() == SegmentKind::cubic) {  // each axis's largest share over the span
    AxisVector share{}, t{};
    for (int k = 0; k <= 8; ++k) {
      seg.tangent_at(len * k / 8.0, t);
      for (std::size_t i = 0; i < n; ++i) share[i] = std::max(share[i], std::abs(t[i]));
    }
    for (std::size_t i = 0; i < n; ++i) limit_by_share(out, axes[i], share[i]);
    add_cubic_curve(out, seg, axes, slope, v_cap_mm_s);
    return out;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (arc && (i == seg.plane_a() || i == seg.plane_b())) continue;
    limit_by_share(out, axes[i], std::abs(p1[i] - p0[i]) / len);
  }
  if (arc) add_arc_plane(out, seg, axes, slope);
  return out;
}

}  // namespace nck::motion
