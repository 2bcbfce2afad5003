#include "nck/report/timed_path.hpp"

#include <algorithm>

namespace nck::app {
namespace {

// Where a run must end: a new block (by_block), G0 / feed or map.
bool same_run_labels(const TimedPoint& a, const TimedPoint& b, bool by_block) {
  if (a.rapid != b.rapid || a.frame != b.frame) return false;
  return !by_block || (a.line == b.line && a.file == b.file);
}

// The streaming thinning of TimedPath::add over a finished list: out keeps
// in's first and last point; every point of in lies within tol (per axis)
// of the linear interpolation in time between the out points around it.
void thin(const std::vector<TimedPoint>& in, double tol, bool by_block, std::vector<TimedPoint>& out) {
  out.clear();
  if (in.empty()) return;
  out.push_back(in.front());
  TimedPath::Fit fit;
  const TimedPoint* tip = nullptr;
  for (std::size_t i = 1; i < in.size(); ++i) {
    const TimedPoint& p = in[i];
    if (tip && same_run_labels(*tip, p, by_block) && fit.fits(out.back(), p)) {
      fit.take(out.back(), p, tol);
    } else {
      if (tip) out.push_back(*tip);
      fit.start(out.back(), p, tol);
    }
    tip = &p;
  }
  if (tip) out.push_back(*tip);
}

}  // namespace

void TimedPath::Fit::start(const TimedPoint& anchor, const TimedPoint& p, double tol) {
  lo_.fill(-1e300);
  hi_.fill(1e300);
  take(anchor, p, tol);
}

bool TimedPath::Fit::fits(const TimedPoint& anchor, const TimedPoint& p) const {
  const double dt = p.t_s - anchor.t_s;
  if (!(dt > 0)) return false;
  for (std::size_t a = 0; a < 3; ++a) {
    const double slope = (p.pos[a] - anchor.pos[a]) / dt;
    if (slope < lo_[a] || slope > hi_[a]) return false;
  }
  return true;
}

void TimedPath::Fit::take(const TimedPoint& anchor, const TimedPoint& p, double tol) {
  const double dt = p.t_s - anchor.t_s;
  if (!(dt > 0)) {  // no time between them: nothing else fits this run
    lo_.fill(1e300);
    hi_.fill(-1e300);
    return;
  }
  for (std::size_t a = 0; a < 3; ++a) {
    lo_[a] = std::max(lo_[a], (p.pos[a] - tol - anchor.pos[a]) / dt);
    hi_[a] = std::min(hi_[a], (p.pos[a] + tol - anchor.pos[a]) / dt);
  }
}

void TimedPath::add(const TimedPoint& p) {
  if (points_.empty()) {
    min_ = max_ = p.pos;
    points_.push_back(p);
    return;
  }
  for (std::size_t a = 0; a < 3; ++a) {
    min_[a] = std::min(min_[a], p.pos[a]);
    max_[a] = std::max(max_[a], p.pos[a]);
  }
  if (has_tip_ && same_run_labels(tip_, p, true) && fit_.fits(points_.back(), p)) {
    fit_.take(points_.back(), p, kTolMm);
    tip_ = p;
    return;
  }
  // The tip ends its run (the last cycle of its block, or where the line
  // leaves the tolerance) and anchors the next one.
  if (has_tip_) points_.push_back(tip_);
  fit_.start(points_.back(), p, kTolMm);
  tip_ = p;
  has_tip_ = true;
  // fit_ stays valid: the thinning keeps the last vertex, the current
  // run's anchor.
  if (points_.size() > kMaxVertices)
    thin_tol_mm_ = thin_until(points_, kMaxVertices / 2, thin_tol_mm_, error_mm_, by_block_);
}

// Thins `points` again until at most max_points remain, with a tolerance
// doubling from twice last_tol_mm, past kMaxBlockTolMm across blocks; if G0
// / feed and map changes alone leave too many, every second point goes. The
// first and last points stay. Returns the last tolerance used.
double TimedPath::thin_until(std::vector<TimedPoint>& points, std::size_t max_points, double last_tol_mm,
                             double& error_mm, bool& by_block) {
  constexpr double kMaxTolMm = 1e6;
  std::vector<TimedPoint> kept;
  for (double tol = std::max(2 * last_tol_mm, 2 * kTolMm); points.size() > max_points; tol *= 2) {
    if (tol > kMaxTolMm) {
      kept.clear();
      for (std::size_t i = 0; i < points.size(); i += 2) kept.push_back(points[i]);
      if (kept.back().t_s != points.back().t_s) kept.push_back(points.back());
      error_mm = kMaxTolMm;  // no bound worth stating
    } else {
      if (tol > kMaxBlockTolMm) by_block = false;
      thin(points, tol, by_block, kept);
      error_mm += tol;
      last_tol_mm = tol;
    }
    points.swap(kept);
  }
  return last_tol_mm;
}

void TimedPath::close() {
  if (has_tip_) points_.push_back(tip_);
  has_tip_ = false;
}

TimedPath::Vertices TimedPath::vertices(std::size_t max_points) const {
  Vertices v{{}, {}, error_mm_, by_block_};
  if (!has_tip_ && points_.size() <= max_points) {
    v.points = points_;
    return v;
  }
  v.thinned.reserve(points_.size() + 1);
  v.thinned.assign(points_.begin(), points_.end());
  if (has_tip_) v.thinned.push_back(tip_);
  (void)thin_until(v.thinned, max_points, thin_tol_mm_, v.error_mm, v.by_block);
  v.points = v.thinned;
  return v;
}

}  // namespace nck::app
