#pragma once
// The decoder's work, counted where it is done: every block a reader reads.
// Loop budgets count iterations, but one iteration may rescan thousands of
// skipped lines ($IF 0 bodies, $GOTO searches, subroutine bodies), so the
// reading itself has a budget too (DecoderConfig::max_lines_read). The first
// pass through the main program is free: a program may be any size, and
// streaming it once is the work it asks for. The same place polls the stop
// request of the caller (DecoderConfig::stop: SIGINT/SIGTERM, --max-wall), so
// no decoding step runs for long without looking at it.
#include <atomic>
#include <cstdint>

namespace nck::nc::detail {

class WorkMeter {
 public:
  enum class Halt : std::uint8_t { none, budget, stop };

  WorkMeter(std::uint64_t max_lines, const std::atomic<bool>* stop) : max_lines_(max_lines), stop_(stop) {}

  // One block read (`free`: the main program's first pass); false when the
  // reading must end here.
  bool count(bool free) noexcept {
    if (halt_ != Halt::none) return false;
    if (stop_ != nullptr && stop_->load(std::memory_order_relaxed)) halt_ = Halt::stop;
    else if (!free && ++lines_ > max_lines_) halt_ = Halt::budget;
    return halt_ == Halt::none;
  }
  Halt halted() const noexcept { return halt_; }
  std::uint64_t lines() const noexcept { return lines_; }
  std::uint64_t max_lines() const noexcept { return max_lines_; }

 private:
  std::uint64_t max_lines_;
  const std::atomic<bool>* stop_;
  std::uint64_t lines_ = 0;  // counted (not free) blocks read
  Halt halt_ = Halt::none;
};

}  // namespace nck::nc::detail
