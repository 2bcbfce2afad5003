#pragma once
// The newest value from one writer thread to one reader thread, without a
// lock and without either side ever waiting: three slots, the writer fills
// its own, then swaps it with the "latest" slot; the reader swaps its own
// with "latest" when the writer has published since. A reader that falls
// behind skips values (it only ever wants the newest), and neither side
// touches a slot the other one owns. The live kernel publishes its state
// this way every cycle (nck serve).
#include <array>
#include <atomic>
#include <cstdint>

namespace nck {

template <class T>
class TripleBuffer {
 public:
  // writer: the slot to fill; publish() hands it over.
  T& back() noexcept { return slots_[back_]; }
  void publish() noexcept {
    const std::uint8_t old = latest_.exchange(static_cast<std::uint8_t>(back_ | kFresh), std::memory_order_acq_rel);
    back_ = old & kIndex;
  }
  // reader: true and the newest value in `front()` if one was published
  // since the last call.
  bool take() noexcept {
    if ((latest_.load(std::memory_order_relaxed) & kFresh) == 0) return false;
    const std::uint8_t old = latest_.exchange(front_, std::memory_order_acq_rel);
    front_ = old & kIndex;
    return true;
  }
  const T& front() const noexcept { return slots_[front_]; }

 private:
  static constexpr std::uint8_t kFresh = 4, kIndex = 3;
  std::array<T, 3> slots_{};
  std::uint8_t back_ = 0;                 // writer's slot
  std::uint8_t front_ = 1;                // reader's slot
  std::atomic<std::uint8_t> latest_{2};   // slot in between (+ kFresh once published)
};

}  // namespace nck
