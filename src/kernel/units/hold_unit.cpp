#include "hold_unit.hpp"

namespace nck::kernel {

void HoldUnit::start_block(const Command& c, const StopMark& mark) noexcept {
  if (!c.emit_block_event) return;  // a follow-up command of the same block
  ++blocks_;
  using K = StopMark::Kind;
  switch (mark.kind) {
    case K::n: mark_pending_ = mark_pending_ || (c.n && *c.n == mark.value); break;
    case K::line: mark_pending_ = mark_pending_ || (c.file_id == 0 && c.line == mark.value); break;
    case K::block: mark_pending_ = mark_pending_ || blocks_ == static_cast<std::uint64_t>(mark.value); break;
    case K::now:
    case K::none: break;
  }
}

// P-CHAN-00015: -1 motion blocks, 0 also blocks with functions or a dwell, 1 every block.
bool HoldUnit::wanted(const Command& c, const ChannelInput& in, bool has_functions) const noexcept {
  if (mark_pending_ || in.stop_at.kind == StopMark::Kind::now) return true;
  if (!in.single_step) return false;
  if (mode_ > 0 || c.is<Motion>()) return true;
  return mode_ == 0 && (has_functions || c.is<Dwell>());
}

std::optional<StateReason> HoldUnit::at_block_end(const Command& c, const ChannelInput& in, bool has_functions,
                                                  bool standing) noexcept {
  const bool committed = committed_;
  committed_ = false;
  if (!wanted(c, in, has_functions)) return std::nullopt;
  // A motion holds where it was planned to stand; anything else only where the path stands.
  if (c.is<Motion>() ? !committed : !standing) return std::nullopt;
  at_mark_ = mark_pending_ || in.stop_at.kind == StopMark::Kind::now;
  mark_pending_ = false;
  return at_mark_ ? StateReason::stop_at : StateReason::single_step;
}

}  // namespace nck::kernel
