#pragma once
// Replays a --plc scenario in the cyclic path: each cycle, due(now) gives the
// actions whose time has come (t_s <= now_s) and that were not given before,
// in order; a triggered line ('@hold cycle_start') is armed when its channel
// first enters its program state (entered()) and comes due its delay later.
// No heap in the cycle (the triggered lines' due times are sized at setup),
// noexcept.
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "nck/kernel/program_state.hpp"
#include "nck/sim/scenario.hpp"

namespace nck::sim {

class ScenarioPlayer {
 public:
  ScenarioPlayer() = default;
  // setup: the scenario must outlive the player (it only keeps a view).
  explicit ScenarioPlayer(const sim::Scenario& sc)
      : actions_(sc.actions), triggered_(sc.triggered), due_s_(sc.triggered.size(), kNotArmed) {}

  std::span<const sim::ScenarioAction> due(double now_s) noexcept {
    const std::size_t first = next_;
    while (next_ < actions_.size() && actions_[next_].t_s <= now_s + kTimeEps_s) ++next_;
    return actions_.subspan(first, next_ - first);
  }
  // Channel ch (1-based) entered program state st in the cycle at t_s. rt
  void entered(std::uint8_t ch, kernel::ProgramState st, double t_s) noexcept;
  // Calls f(action) for each armed triggered line whose time has come. rt
  template <class F>
  void for_each_triggered_due(double now_s, F&& f) noexcept {
    if (armed_ == 0) return;
    for (std::size_t i = 0; i < triggered_.size(); ++i)
      if (due_s_[i] <= now_s + kTimeEps_s) {
        due_s_[i] = kDone;
        --armed_;
        f(triggered_[i]);
      }
  }
  bool has_triggers() const noexcept { return !triggered_.empty(); }
  // Nothing more to come: every timed line given, no triggered line armed
  // (one that waits for a state never entered does not keep a run alive).
  bool finished() const noexcept { return next_ >= actions_.size() && armed_ == 0; }
  void rewind() noexcept { next_ = 0; }

 private:
  static constexpr double kTimeEps_s = 1e-9;  // same rounding guard as the PLC's delays
  static constexpr double kNotArmed = std::numeric_limits<double>::infinity();
  static constexpr double kDone = std::numeric_limits<double>::max();  // > any time, never due again

  std::span<const sim::ScenarioAction> actions_;
  std::span<const sim::ScenarioAction> triggered_;
  std::vector<double> due_s_;  // per triggered line: when it acts (kNotArmed, or kDone once given)
  std::size_t armed_ = 0;
  std::size_t next_ = 0;
};

}  // namespace nck::sim
