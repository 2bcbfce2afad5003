#pragma once
// Replays a --plc scenario in the cyclic path: each cycle, due(now) gives the
// actions whose time has come (t_s <= now_s) and that were not given before,
// in order. No heap, noexcept.
#include <cstddef>
#include <span>

#include "nck/sim/scenario.hpp"

namespace nck::sim {

class ScenarioPlayer {
 public:
  ScenarioPlayer() = default;
  // The scenario must outlive the player (it only keeps a view).
  explicit ScenarioPlayer(const sim::Scenario& sc) noexcept : actions_(sc.actions) {}

  std::span<const sim::ScenarioAction> due(double now_s) noexcept;
  bool finished() const noexcept { return next_ >= actions_.size(); }
  void rewind() noexcept { next_ = 0; }

 private:
  std::span<const sim::ScenarioAction> actions_;
  std::size_t next_ = 0;
};

}  // namespace nck::sim
