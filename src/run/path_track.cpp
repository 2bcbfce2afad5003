#include "nck/run/path_track.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "nck/report/backplot_axes.hpp"

namespace nck::app {
namespace {

using json = nlohmann::ordered_json;

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// The point of segment p-q nearest to x, and its distance.
std::pair<std::array<double, 3>, double> nearest_on(const std::array<double, 3>& p, const std::array<double, 3>& q,
                                                    const std::array<double, 3>& x) {
  std::array<double, 3> d{}, w{};
  double dd = 0, dw = 0;
  for (int k = 0; k < 3; ++k) {
    d[k] = q[k] - p[k];
    dd += d[k] * d[k];
    dw += d[k] * (x[k] - p[k]);
  }
  const double u = dd > 0 ? std::clamp(dw / dd, 0.0, 1.0) : 0.0;
  for (int k = 0; k < 3; ++k) w[k] = p[k] + u * d[k];
  return {w, distance(w, x)};
}

json rounded(const std::array<double, 3>& p) {
  json a = json::array();
  for (double v : p) a.push_back(std::round(v * 1e4) / 1e4);
  return a;
}

}  // namespace

void PathTrack::start(const config::Machine& m) {
  if (m.channels.empty()) return;
  axis_ = backplot_axes(m.channels[0]);
  for (int a = 0; a < 3; ++a)
    if (axis_[a] >= 0) names_[a] = m.channels[0].axes[static_cast<std::size_t>(axis_[a])].name;
}

void PathTrack::take(const kernel::TickOutput& out) {
  for (const kernel::Event& e : out.events)
    if (e.channel == 1 && e.kind() == kernel::EventKind::block) line_ = e.at.line;
  std::array<double, 3> p{};
  for (int a = 0; a < 3; ++a)
    if (axis_[a] >= 0) p[a] = out.channels[0].axis_mcs[static_cast<std::size_t>(axis_[a])];
  if (!started_) {
    started_ = true;
    last_ = p;
    points_.push_back({p, 0, out.t_s, line_});
    return;
  }
  const double step = distance(p, last_);
  if (step <= 0) return;
  s_mm_ += step;
  last_ = p;
  if (s_mm_ - points_.back().s_mm < spacing_mm_) return;
  points_.push_back({p, s_mm_, out.t_s, line_});
  if (points_.size() < kMaxPoints) return;
  std::size_t keep = 0;  // every other point, the first kept
  for (std::size_t i = 0; i < points_.size(); i += 2) points_[keep++] = points_[i];
  points_.resize(keep);
  spacing_mm_ *= 2;
}

json PathTrack::ghost_json(std::size_t max_points) const {
  const std::size_t stride = std::max<std::size_t>(1, (points_.size() + max_points - 1) / std::max<std::size_t>(max_points, 1));
  json x = json::array(), y = json::array(), z = json::array(), line = json::array();
  for (std::size_t i = 0; i < points_.size(); i += stride) {
    const Point& p = points_[i];
    x.push_back(std::round(p.pos[0] * 1e4) / 1e4);
    y.push_back(std::round(p.pos[1] * 1e4) / 1e4);
    z.push_back(std::round(p.pos[2] * 1e4) / 1e4);
    line.push_back(p.line);
  }
  return {{"axes", names_}, {"x", x}, {"y", y}, {"z", z}, {"line", line}};
}

namespace {

// The window: far enough ahead to follow B where it is shorter or longer
// (corner rounding, another contour), near enough never to reach a pass of
// the tool over the same place much later in the program.
constexpr double kWindowMm = 20;
// A distance this much larger is a rise, not rounding.
constexpr double kRiseMm = 1e-9;
// A point further ahead replaces the first valley only when it is nearer by
// more than this and by more than half: B left A's path there (a detour,
// a contour of its own) and A has moved on.
constexpr double kJumpMm = 0.01;

struct Match {
  std::size_t j = 0;  // B's segment j .. j + 1
  double d_mm = -1;
  std::array<double, 3> at{};
};

// The point of B's path nearest to x, searched along the path from segment
// `cursor`: B may first go as far as A went since its last point
// (`reach_mm`: past a turn such as a plunge's bottom, B must follow A up),
// then on while the distance does not rise (the first valley), since a
// later pass over the same place (a retract along the plunge, a loop's next
// turn) lies beyond a rise. The rest of the window is searched only to
// leave a valley B no longer shares with A.
Match nearest_along(const std::vector<PathTrack::Point>& pb, std::size_t cursor, const std::array<double, 3>& x,
                    double reach_mm) {
  const double s_end_mm = pb[cursor].s_mm + kWindowMm;
  const double s_reach_mm = pb[cursor + 1].s_mm + reach_mm;
  const auto at = [&](std::size_t j) {
    const auto [w, d] = nearest_on(pb[j].pos, pb[j + 1].pos, x);
    return Match{j, d, w};
  };
  Match valley = at(cursor);
  std::size_t j = cursor + 1;
  for (; j + 1 < pb.size() && pb[j].s_mm <= s_end_mm; ++j) {
    const Match m = at(j);
    if (pb[j].s_mm > s_reach_mm && m.d_mm > valley.d_mm + kRiseMm) break;
    if (m.d_mm < valley.d_mm) valley = m;  // a tie keeps the earlier segment
  }
  Match best = valley;
  for (; j + 1 < pb.size() && pb[j].s_mm <= s_end_mm; ++j)
    if (const Match m = at(j); m.d_mm < best.d_mm) best = m;
  return best.d_mm < std::min(valley.d_mm / 2, valley.d_mm - kJumpMm) ? best : valley;
}

}  // namespace

json compare_paths(const PathTrack& a, const PathTrack& b, std::size_t top) {
  const auto& pa = a.points();
  const auto& pb = b.points();
  struct Hit {
    double d_mm = -1;
    std::size_t ia = 0;
    std::array<double, 3> at_b{};
    std::uint32_t line_b = 0;
  };
  std::map<std::uint32_t, Hit> worst;  // per NC line of A
  double max_mm = 0, sum_mm = 0;
  std::size_t cursor = 0;  // the cursor only moves forward
  for (std::size_t i = 0; i < pa.size() && pb.size() > 1; ++i) {
    const Match m = nearest_along(pb, cursor, pa[i].pos, i > 0 ? pa[i].s_mm - pa[i - 1].s_mm : 0.0);
    cursor = m.j;
    max_mm = std::max(max_mm, m.d_mm);
    sum_mm += m.d_mm;
    Hit& h = worst[pa[i].line];
    if (m.d_mm > h.d_mm) h = {m.d_mm, i, m.at, pb[m.j + 1].line};
  }
  std::vector<Hit> hits;
  for (const auto& [line, h] : worst) hits.push_back(h);
  std::sort(hits.begin(), hits.end(), [](const Hit& x, const Hit& y) { return x.d_mm > y.d_mm; });
  json rows = json::array();
  for (std::size_t k = 0; k < hits.size() && k < top; ++k) {
    const PathTrack::Point& p = pa[hits[k].ia];
    rows.push_back({{"line_a", p.line}, {"line_b", hits[k].line_b}, {"s_mm", std::round(p.s_mm * 1e3) / 1e3},
                    {"t_s", p.t_s}, {"a", rounded(p.pos)}, {"b", rounded(hits[k].at_b)},
                    {"distance_mm", std::round(hits[k].d_mm * 1e4) / 1e4}});
  }
  const double len_a = pa.empty() ? 0 : pa.back().s_mm, len_b = pb.empty() ? 0 : pb.back().s_mm;
  return {{"axes", a.axis_names()},
          {"length_a_mm", std::round(len_a * 1e3) / 1e3},
          {"length_b_mm", std::round(len_b * 1e3) / 1e3},
          {"max_mm", std::round(max_mm * 1e4) / 1e4},
          {"mean_mm", pa.empty() ? 0.0 : std::round(sum_mm / static_cast<double>(pa.size()) * 1e4) / 1e4},
          {"largest", rows}};
}

}  // namespace nck::app
