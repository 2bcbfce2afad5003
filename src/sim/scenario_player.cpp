// Scenario replay: the actions whose time has come (rt).
#include "nck/sim/scenario_player.hpp"

namespace nck::sim {

void ScenarioPlayer::entered(std::uint8_t ch, kernel::ProgramState st, double t_s) noexcept {
  for (std::size_t i = 0; i < triggered_.size(); ++i)
    if (due_s_[i] == kNotArmed && triggered_[i].channel == ch && triggered_[i].trigger == st) {
      due_s_[i] = t_s + triggered_[i].t_s;
      ++armed_;
    }
}

}  // namespace nck::sim
