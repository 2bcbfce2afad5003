// Scenario replay: the actions whose time has come (rt).
#include "nck/sim/scenario_player.hpp"

namespace nck::sim {
namespace {

constexpr double kTimeEps_s = 1e-9;  // same rounding guard as the PLC's delays

}  // namespace

std::span<const sim::ScenarioAction> ScenarioPlayer::due(double now_s) noexcept {
  const std::size_t first = next_;
  while (next_ < actions_.size() && actions_[next_].t_s <= now_s + kTimeEps_s) ++next_;
  return actions_.subspan(first, next_ - first);
}

}  // namespace nck::sim
