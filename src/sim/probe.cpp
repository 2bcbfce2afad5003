#include "nck/sim/probe.hpp"

namespace nck::sim {

bool Probe::watch(const Positions& now) noexcept {
  const Positions before = last_;
  last_ = now;
  if (axis_ < 0 || !started_) {
    started_ = true;
    return false;
  }
  const auto a = static_cast<std::size_t>(axis_);
  const double p = switch_pos_mm_, d = now[a] - before[a];
  if (d == 0 || (before[a] - p) * (now[a] - p) > 0) return false;
  const double f = (p - before[a]) / d;
  for (std::size_t j = 0; j < n_axes_; ++j) latched_[j] = before[j] + f * (now[j] - before[j]);
  return true;
}

}  // namespace nck::sim
