#include "nck/report/report_series.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace nck::app {

namespace {

// |v| · 10^decimals as an integer, when that fits a double's exact integers:
// the report's numbers almost always do, and then writing them is a few
// integer divisions instead of an exact decimal conversion (~500
// instructions each, ~10^5 numbers per report). The last digit may differ
// from exact decimal rounding when v·10^d lies within one ulp of a half:
// invisible in a plot.
bool append_scaled(std::string& out, double v, int decimals) {
  static constexpr double kPow10[] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8};
  if (decimals < 0 || decimals > 8) return false;
  const double scaled = std::fabs(v) * kPow10[decimals];
  if (!(scaled < 1e12)) return false;  // v·10^d then errs by < 10^-4 of a last digit
  auto n = static_cast<std::uint64_t>(std::nearbyint(scaled));  // ties to even, as exact rounding
  if (n == 0) {
    out += '0';
    return true;
  }
  char buf[32];
  char* p = buf + sizeof buf;
  int d = decimals;
  while (d > 0 && n % 10 == 0) {  // trailing zeros of the fraction are not written
    n /= 10;
    --d;
  }
  for (; d > 0; --d, n /= 10) *--p = static_cast<char>('0' + n % 10);
  if (p != buf + sizeof buf) *--p = '.';
  do *--p = static_cast<char>('0' + n % 10);
  while ((n /= 10) != 0);
  if (v < 0) *--p = '-';
  out.append(p, buf + sizeof buf);
  return true;
}

}  // namespace

void append_number(std::string& out, double v, int decimals) {
  if (!std::isfinite(v)) v = 0;
  if (append_scaled(out, v, decimals)) return;
  const std::size_t at = out.size();
  char buf[512];  // a finite double in fixed notation: ≤ 309 digits + decimals
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, std::clamp(decimals, 0, 17));
  out.append(buf, r.ptr);
  if (out.find('.', at) == std::string::npos) return;
  while (out.back() == '0') out.pop_back();
  if (out.back() == '.') out.pop_back();
  if (out.compare(at, std::string::npos, "-0") == 0) out.erase(at, 1);
}

void EnvelopeSeries::start(std::size_t series_count, double cycle_s) {
  n_ = series_count;
  buckets_.clear();
  buckets_.reserve(kMaxBuckets * n_);
  cycle_s_ = cycle_s;
}

void EnvelopeSeries::add(std::uint64_t cycle, std::span<const double> values) {
  if (!started_) {
    first_cycle_ = cycle;
    started_ = true;
  }
  const auto value = [&](std::size_t s) { return static_cast<float>(s < values.size() ? values[s] : 0.0); };
  const std::uint64_t rel = cycle - first_cycle_;
  if (rel >= next_start_) {  // a new bucket (or, after a jump, several)
    while (rel / stride_ >= kMaxBuckets) merge_pairs();
    const std::size_t k = rel / stride_;
    count_ = k + 1;
    next_start_ = (k + 1) * stride_;
    buckets_.resize(count_ * n_, Bucket{});
    Bucket* row = &buckets_[k * n_];
    for (std::size_t s = 0; s < n_; ++s) {
      const float v = value(s);
      row[s] = {v, v, true};
    }
    return;
  }
  // Most cycles: the envelope of the bucket under way widens (one stride in
  // 4,096 buckets is hundreds of cycles). A bucket's series lie side by side;
  // a series without a value keeps its 0, which the bucket holds already.
  Bucket* row = &buckets_[(count_ - 1) * n_];
  const std::size_t n = std::min(n_, values.size());
  for (std::size_t s = 0; s < n; ++s) {
    const auto v = static_cast<float>(values[s]);
    Bucket& x = row[s];
    if (v < x.min) {
      x.min = v;
      x.min_first = false;  // the minimum now comes after the maximum
    }
    if (v > x.max) {
      x.max = v;
      x.min_first = true;
    }
  }
}

void EnvelopeSeries::merge_pairs() {
  const std::size_t merged = (count_ + 1) / 2;
  for (std::size_t out = 0; out < merged; ++out)
    for (std::size_t s = 0; s < n_; ++s) {
      const std::size_t i = 2 * out;
      const Bucket a = buckets_[i * n_ + s];
      if (i + 1 >= count_) {
        buckets_[out * n_ + s] = a;
        continue;
      }
      const Bucket c = buckets_[(i + 1) * n_ + s];
      const bool min_in_a = a.min <= c.min, max_in_a = a.max >= c.max;
      Bucket m{std::min(a.min, c.min), std::max(a.max, c.max), true};
      if (min_in_a && max_in_a) m.min_first = a.min_first;
      else if (!min_in_a && !max_in_a) m.min_first = c.min_first;
      else m.min_first = min_in_a;
      buckets_[out * n_ + s] = m;
    }
  count_ = merged;
  buckets_.resize(count_ * n_);
  stride_ *= 2;
  next_start_ = count_ * stride_;
}

std::string EnvelopeSeries::json(std::span<const int> decimals) const {
  std::string s = "{\"t\":[";
  const bool pairs = stride_ > 1;
  const double bucket_s = static_cast<double>(stride_) * cycle_s_;
  const double t0 = static_cast<double>(first_cycle_) * cycle_s_;
  for (std::size_t k = 0; k < count_; ++k) {
    if (k > 0) s += ',';
    const double t = t0 + static_cast<double>(k) * bucket_s;
    append_number(s, t, 4);
    if (pairs) {
      s += ',';
      append_number(s, t + bucket_s / 2, 4);
    }
  }
  s += "],\"v\":[";
  for (std::size_t i = 0; i < n_; ++i) {
    if (i > 0) s += ',';
    s += '[';
    const int d = i < decimals.size() ? decimals[i] : 3;
    for (std::size_t k = 0; k < count_; ++k) {
      const Bucket& b = buckets_[k * n_ + i];
      if (k > 0) s += ',';
      append_number(s, b.min_first ? b.min : b.max, d);
      if (pairs) {
        s += ',';
        append_number(s, b.min_first ? b.max : b.min, d);
      }
    }
    s += ']';
  }
  return s + "]}";
}

double distance_to_line(const std::array<float, 3>& p, const std::array<float, 3>& a, const std::array<float, 3>& b) {
  double ab[3], ap[3], len2 = 0;
  for (int i = 0; i < 3; ++i) {
    ab[i] = double(b[i]) - double(a[i]);
    ap[i] = double(p[i]) - double(a[i]);
    len2 += ab[i] * ab[i];
  }
  if (len2 <= 0) return std::sqrt(ap[0] * ap[0] + ap[1] * ap[1] + ap[2] * ap[2]);
  // |ap x ab| / |ab|
  const double cx = ap[1] * ab[2] - ap[2] * ab[1], cy = ap[2] * ab[0] - ap[0] * ab[2],
               cz = ap[0] * ab[1] - ap[1] * ab[0];
  return std::sqrt((cx * cx + cy * cy + cz * cz) / len2);
}

namespace {

std::array<float, 3> to_float(const std::array<double, 3>& p) {
  return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
}

// Reumann-Witkam: a run of points stays one segment while every point lies
// within tol of the line through the run's first point and its direction
// at the start; `breaks(a, b)` forces a vertex between two points.
template <class Breaks>
void thin(const std::vector<PathPoint>& in, double tol, Breaks breaks, std::vector<PathPoint>& out) {
  out.clear();
  if (in.empty()) return;
  out.push_back(in.front());
  std::size_t dir_from = 0;  // the run: in[dir_from] (the anchor) and in[dir_from + 1] give the direction
  for (std::size_t i = 1; i < in.size(); ++i) {
    const bool same_run = i > dir_from + 1 && !breaks(in[i - 1], in[i]) &&
                          distance_to_line(in[i].pos, in[dir_from].pos, in[dir_from + 1].pos) <= tol;
    if (same_run) {
      out.back() = in[i];  // the run's end moves on
      continue;
    }
    if (i > dir_from + 1) dir_from = i - 1;  // the previous end is a vertex; a new run starts there
    out.push_back(in[i]);
  }
}

bool breaks_run(const PathPoint& a, const PathPoint& b) { return a.rapid != b.rapid || a.frame != b.frame; }

}  // namespace

void PathRecorder::add(const std::array<double, 3>& pos, std::uint32_t line, std::uint16_t file, bool rapid,
                       std::uint32_t frame, double t_s) {
  if (points_.empty()) {
    min_ = max_ = tip_ = pos;
    // Room for every vertex kept: pages are touched only as the path grows,
    // and the vector never moves (a doubling copies megabytes and faults in
    // pages twice).
    points_.reserve(kMaxVertices + 1);
    points_.push_back({to_float(pos), line, file, rapid, frame, t_s});
    anchor_ = pos;
    has_dir_ = false;
    return;
  }
  for (int i = 0; i < 3; ++i) {
    min_[i] = std::min(min_[i], pos[i]);
    max_[i] = std::max(max_[i], pos[i]);
  }
  PathPoint& tip = points_.back();
  if (pos == tip_) return;  // standing still
  const bool same_block = tip.line == line && tip.file == file && tip.rapid == rapid && tip.frame == frame;
  if (has_dir_ && same_block) {
    // distance of pos from the run's line (anchor, direction)
    double ap[3], cross2 = 0;
    for (int i = 0; i < 3; ++i) ap[i] = pos[i] - anchor_[i];
    const double c[3] = {ap[1] * dir_[2] - ap[2] * dir_[1], ap[2] * dir_[0] - ap[0] * dir_[2],
                         ap[0] * dir_[1] - ap[1] * dir_[0]};
    for (double v : c) cross2 += v * v;
    if (cross2 <= kRecordTolMm * kRecordTolMm) {
      tip = {to_float(pos), line, file, rapid, frame, t_s};
      tip_ = pos;
      return;
    }
  }
  double step[3], len = 0;
  for (int i = 0; i < 3; ++i) {
    step[i] = pos[i] - tip_[i];
    len += step[i] * step[i];
  }
  len = std::sqrt(len);
  if (same_block && len < kMinStepMm) {  // creeping: the tip moves, no new vertex
    tip = {to_float(pos), line, file, rapid, frame, t_s};
    tip_ = pos;
    return;
  }
  // The tip becomes a vertex and the anchor of a new run towards pos.
  anchor_ = tip_;
  has_dir_ = len >= kMinStepMm;  // a new block's first step may be tiny: no direction yet
  if (has_dir_)
    for (int i = 0; i < 3; ++i) dir_[i] = step[i] / len;
  points_.push_back({to_float(pos), line, file, rapid, frame, t_s});
  tip_ = pos;
  if (points_.size() > kMaxVertices) thin_in_place();
}

// Halves the vertices at least: thinned with a tolerance doubling from
// twice the last one; if breaks (G0/G1, maps) alone leave too many, every
// second vertex goes. The newest point stays the tip.
void PathRecorder::thin_in_place() {
  constexpr double kMaxTolMm = 1e6;
  const PathPoint tip = points_.back();
  // Thinned into a second buffer of the same room, then swapped: no
  // allocation and no fresh pages after the first time.
  scratch_.reserve(kMaxVertices + 1);
  for (double tol = std::max(2 * thin_tol_mm_, 2 * kRecordTolMm); points_.size() > kMaxVertices / 2; tol *= 2) {
    if (tol > kMaxTolMm) {
      scratch_.clear();
      for (std::size_t i = 0; i < points_.size(); i += 2) scratch_.push_back(points_[i]);
      points_.swap(scratch_);
      break;
    }
    thin(points_, tol, breaks_run, scratch_);
    points_.swap(scratch_);
    thin_tol_mm_ = tol;
  }
  if (points_.empty() || points_.back().pos != tip.pos) points_.push_back(tip);
  has_dir_ = false;  // the next point starts a new run from the tip
  anchor_ = tip_;
}

std::vector<PathPoint> PathRecorder::simplified(double tol_mm) const {
  // a new map starts a new run: the page draws each point in its own block's program coordinates
  std::vector<PathPoint> out;
  thin(points_, tol_mm, breaks_run, out);
  return out;
}

}  // namespace nck::app
