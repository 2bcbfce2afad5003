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

std::optional<StateReason> HoldUnit::at_block_end(const Command& c, const ChannelInput& in, bool has_functions,
                                                  bool standing) noexcept {
  const bool committed = committed_;
  committed_ = false;
  if (!wanted(c, in, has_functions)) return std::nullopt;
  // A motion holds where it was planned to stand; anything else only where the path stands.
  if (c.is<Motion>() ? !committed : !standing) return std::nullopt;
  holding_at_mark_ = at_mark(in);
  mark_pending_ = false;
  return holding_at_mark_ ? StateReason::stop_at : StateReason::single_step;
}

}  // namespace nck::kernel
