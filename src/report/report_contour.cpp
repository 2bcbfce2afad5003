#include "nck/report/report_contour.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "nck/core/plane.hpp"
#include "nck/prep/planner.hpp"

namespace nck::app {
namespace {

bool is_arc(const nc::Block& b) { return b.modal.motion == nc::Motion::cw || b.modal.motion == nc::Motion::ccw; }

// A block that moves the axes to the positions its words give (what
// compensation rewrites); G74/G92/G101/G102/G100/G200 words mean something else.
bool moves_to_words(const nc::Block& b) {
  const nc::Motion m = b.modal.motion;
  if (m != nc::Motion::rapid && m != nc::Motion::linear && !is_arc(b)) return false;
  constexpr nc::GCodeSet kOther{nc::GCode::g74, nc::GCode::g92, nc::GCode::g101, nc::GCode::g102, nc::GCode::g100};
  return !b.manual_g && !b.g_nonmodal.has_any(kOther);
}

}  // namespace

void ProgrammedContour::decoded(const nc::Block& b, const prep::Planner& planner, bool trc_holding) {
  const bool comp = b.modal.radius_comp != nc::RadiusComp::g40;
  if (!tracking_) {
    // The selection starts where the planner stands when nothing is held;
    // while compensation still holds the last G40 line, where that ended.
    if (!comp || (trc_holding && runs_.empty())) return;
    tracking_ = true;
    if (!trc_holding) pos_ = planner.planned_pcs();
    runs_.emplace_back();
    runs_.back().first_line = b.line;
    add(pos_, planner);
  }
  runs_.back().last_line = b.line;
  if (moves_to_words(b)) move(b, planner);
  if (!comp) tracking_ = false;  // the G40 block ends the stretch
}

void ProgrammedContour::move(const nc::Block& b, const prep::Planner& planner) {
  const motion::AxisVector from = pos_;
  for (std::size_t j = 0; j < planner.axis_count(); ++j) {
    if (!b.axes[j]) continue;
    const double v = *b.axes[j] / (planner.word_is_diameter(b, j) ? 2.0 : 1.0);
    pos_[j] = b.modal.absolute ? v : pos_[j] + v;
  }
  if (is_arc(b)) arc_points(b, planner, from);
  add(pos_, planner);
}

// The chords of a G2/G3 in its plane (centre from I/J/K or R, as the
// compensation reads them); the third axis moves in proportion (helix).
void ProgrammedContour::arc_points(const nc::Block& b, const prep::Planner& planner, const motion::AxisVector& from) {
  const PlaneAxes pa = plane_axes(b.modal.plane);
  const int ja = axis_[static_cast<std::size_t>(pa.first)], jb = axis_[static_cast<std::size_t>(pa.second)];
  if (ja < 0 || jb < 0) return;
  const auto a = static_cast<std::size_t>(ja), bb = static_cast<std::size_t>(jb);
  const double sa = from[a], sb = from[bb], ea = pos_[a], eb = pos_[bb];
  const bool ccw = b.modal.motion == nc::Motion::ccw;
  double ca = 0, cb = 0;
  const auto& ci = b.ijk[static_cast<std::size_t>(pa.first)];
  const auto& cj = b.ijk[static_cast<std::size_t>(pa.second)];
  if (ci || cj) {
    ca = (b.modal.circle_center_absolute ? 0 : sa) + ci.value_or(0);
    cb = (b.modal.circle_center_absolute ? 0 : sb) + cj.value_or(0);
  } else if (b.r) {
    const double da = ea - sa, db = eb - sb, half = std::hypot(da, db) / 2;
    if (half < 1e-9) return;
    const double h = std::sqrt(std::max(*b.r * *b.r - half * half, 0.0));
    const double side = (ccw ? 1.0 : -1.0) * (*b.r > 0 ? 1.0 : -1.0);
    ca = sa + da / 2 - side * h * db / (2 * half);
    cb = sb + db / 2 + side * h * da / (2 * half);
  } else {
    return;
  }
  const double r = std::hypot(sa - ca, sb - cb);
  const double a0 = std::atan2(sb - cb, sa - ca), a1 = std::atan2(eb - cb, ea - ca);
  double sweep = ccw ? a1 - a0 : a0 - a1;
  while (sweep <= 1e-12) sweep += 2 * std::numbers::pi;
  const int n = std::max(2, static_cast<int>(std::ceil(sweep * 180 / std::numbers::pi / kMaxChordDeg)));
  for (int i = 1; i < n; ++i) {
    const double f = static_cast<double>(i) / n, ang = a0 + (ccw ? 1 : -1) * sweep * f;
    motion::AxisVector p = from;
    for (std::size_t j = 0; j < planner.axis_count(); ++j) p[j] = from[j] + (pos_[j] - from[j]) * f;
    p[a] = ca + r * std::cos(ang);
    p[bb] = cb + r * std::sin(ang);
    add(p, planner);
  }
}

void ProgrammedContour::add(const motion::AxisVector& pcs, const prep::Planner& planner) {
  if (points_ >= kMaxPoints || runs_.empty()) return;
  ++points_;
  const motion::AxisVector mcs = planner.frames().to_mcs(pcs, frames::SuppressMask::none());
  ContourPoint p;
  for (std::size_t k = 0; k < 3; ++k)
    if (axis_[k] >= 0) {
      p.mcs[k] = static_cast<float>(mcs[static_cast<std::size_t>(axis_[k])]);
      p.pcs[k] = static_cast<float>(pcs[static_cast<std::size_t>(axis_[k])]);
    }
  runs_.back().points.push_back(p);
}

}  // namespace nck::app
