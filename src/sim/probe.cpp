#include "nck/sim/probe.hpp"

namespace nck::sim {

bool Probe::watch_axis(const Positions& now) noexcept {
  const auto a = static_cast<std::size_t>(axis_);
  const double p = switch_pos_mm_, d = now[a] - last_[a];
  const bool switched = started_ && d != 0 && (last_[a] - p) * (now[a] - p) <= 0;
  if (switched) {
    const double f = (p - last_[a]) / d;
    for (std::size_t j = 0; j < n_axes_; ++j) latched_[j] = last_[j] + f * (now[j] - last_[j]);
  }
  for (std::size_t j = 0; j < n_axes_; ++j) last_[j] = now[j];
  started_ = true;
  return switched;
}

}  // namespace nck::sim
