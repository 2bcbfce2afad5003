#include "nck/plc/ext_command.hpp"

namespace nck::plc {

std::uint32_t ExtCommandQueue::push(ExtSpindleCommand cmd) noexcept {
  if (queue_.full()) return 0;
  cmd.seq = next_seq_++;
  if (next_seq_ == 0) next_seq_ = 1;
  queue_.push(cmd);
  return cmd.seq;
}

bool ExtCommandQueue::pop(ExtSpindleCommand& out) noexcept {
  if (queue_.empty()) return false;
  out = queue_.front();
  queue_.pop();
  return true;
}

void ExtCommandQueue::acknowledge(std::uint32_t seq) noexcept {
  if (seq == 0) return;
  if (acks_.full()) acks_.pop();  // forget the oldest
  acks_.push(seq);
  last_ack_ = seq;
}

bool ExtCommandQueue::acknowledged(std::uint32_t seq) const noexcept {
  for (std::size_t i = 0; i < acks_.size(); ++i)
    if (acks_.at(i) == seq) return true;
  return false;
}

void ExtCommandQueue::clear() noexcept { queue_.clear(); }

}  // namespace nck::plc
