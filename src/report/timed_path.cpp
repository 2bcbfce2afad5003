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
    // Room for every vertex kept: pages are touched only as the path grows,
    // and the vector never moves (a doubling copies megabytes).
    points_.reserve(kMaxVertices + 1);
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
  if (points_.size() > kMaxVertices) thin_in_place();
}

// Halves the vertices at least: thinned again with a tolerance doubling
// from twice the last one, past kMaxBlockTolMm across blocks; if G0 / feed
// and map changes alone leave too many, every second vertex goes. The
// last vertex (the current run's anchor) stays.
void TimedPath::thin_in_place() {
  constexpr double kMaxTolMm = 1e6;
  const TimedPoint anchor = points_.back();
  scratch_.reserve(kMaxVertices + 1);
  for (double tol = std::max(2 * thin_tol_mm_, 2 * kTolMm); points_.size() > kMaxVertices / 2; tol *= 2) {
    if (tol > kMaxTolMm) {
      scratch_.clear();
      for (std::size_t i = 0; i < points_.size(); i += 2) scratch_.push_back(points_[i]);
      if (scratch_.back().t_s != anchor.t_s) scratch_.push_back(anchor);
      points_.swap(scratch_);
      error_mm_ = kMaxTolMm;  // no bound worth stating
      break;
    }
    if (tol > kMaxBlockTolMm) by_block_ = false;
    thin(points_, tol, by_block_, scratch_);
    points_.swap(scratch_);
    thin_tol_mm_ = tol;
    error_mm_ += tol;
  }
  // fit_ stays valid: add() thins right after a new run began at the
  // anchor, which every thinning keeps as the last vertex.
}

TimedPath::Vertices TimedPath::vertices(std::size_t max_points) const {
  Vertices v{points_, error_mm_, by_block_};
  if (has_tip_) v.points.push_back(tip_);
  std::vector<TimedPoint> scratch;
  for (double tol = std::max(2 * thin_tol_mm_, 2 * kTolMm); v.points.size() > max_points; tol *= 2) {
    if (tol > 1e6) {  // G0 / feed and map changes alone are too many: every second vertex
      scratch.clear();
      for (std::size_t i = 0; i < v.points.size(); i += 2) scratch.push_back(v.points[i]);
      v.points.swap(scratch);
      v.error_mm = 1e6;
      continue;
    }
    if (tol > kMaxBlockTolMm) v.by_block = false;
    thin(v.points, tol, v.by_block, scratch);
    v.points.swap(scratch);
    v.error_mm += tol;
  }
  return v;
}

}  // namespace nck::app
