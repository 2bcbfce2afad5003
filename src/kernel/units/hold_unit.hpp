#pragma once
// The operator's holds at block ends: single step (the HLI switch, where
// P-CHAN-00015 says) and a stop-at mark. A hold never comes mid-block and
// never by braking harder than the path's a_max: a motion holds at its end
// only once the path can stop there within its deceleration (the braking
// staircase of motion/path_profile.hpp); until then the hold moves on to the
// first block end where it can. A block without motion holds only when the
// path stands (it may pass through one at speed).
#include <cstdint>
#include <optional>

#include "nck/kernel/command.hpp"
#include "nck/kernel/program_state.hpp"
#include "nck/kernel/tick_io.hpp"
#include "path_unit.hpp"

namespace nck::kernel {

class HoldUnit {
 public:
  // setup: P-CHAN-00015 (-1 motion blocks, 0 also blocks with functions, 1 every block).
  void setup(std::int8_t single_step_mode) noexcept { mode_ = single_step_mode; }
  // A block starts: is it the stop-at mark? rt
  void start_block(const Command& c, const StopMark& mark) noexcept;
  // Every cycle of motion c, before its step: once a hold is wanted and the
  // path can stop at this block's end, it will. rt
  // (Inline: nothing to do in nearly every cycle.)
  void follow(const Command& c, const ChannelInput& in, bool has_functions, PathUnit& path, double dt_s) noexcept {
    if (!committed_ && wanted(c, in, has_functions)) committed_ = path.end_at_standstill(dt_s);
  }
  // Block c ended (`standing`: the path stands): why the channel holds
  // now, if it does. rt
  std::optional<StateReason> at_block_end(const Command& c, const ChannelInput& in, bool has_functions,
                                          bool standing) noexcept;
  // A cycle starts. rt
  void begin_cycle() noexcept { released_now_ = false; }
  // Cycle start releases one hold per cycle (a press is one step) — one at
  // a stop-at mark only once the caller took the mark away (a live session
  // clears it with the start). rt
  bool released(const ChannelInput& in) noexcept {
    if (!in.cycle_start || released_now_ || (holding_at_mark_ && in.stop_at.kind != StopMark::Kind::none)) return false;
    holding_at_mark_ = false;
    released_now_ = true;
    return true;
  }
  // Program end or reset: nothing pending.
  void reset() noexcept { mark_pending_ = committed_ = holding_at_mark_ = false; }

 private:
  // The block that runs is the stop-at mark's (or one after it).
  bool at_mark(const ChannelInput& in) const noexcept {
    return mark_pending_ || in.stop_at.kind == StopMark::Kind::now;
  }
  // P-CHAN-00015: -1 motion blocks, 0 also blocks with functions or a dwell, 1 every block.
  bool wanted(const Command& c, const ChannelInput& in, bool has_functions) const noexcept {
    if (at_mark(in)) return true;
    if (!in.single_step) return false;
    if (mode_ > 0 || c.is<Motion>()) return true;
    return mode_ == 0 && (has_functions || c.is<Dwell>());
  }

  std::int8_t mode_ = 0;
  std::uint64_t blocks_ = 0;   // blocks started (block:K of a stop-at mark)
  bool mark_pending_ = false;  // the stop-at mark's block ran: hold at the first block end possible
  bool committed_ = false;     // the motion that runs ends at standstill for a hold
  bool holding_at_mark_ = false;  // the channel holds at its stop-at mark
  bool released_now_ = false;  // a hold was released in this cycle
};

}  // namespace nck::kernel
