#pragma once
// A single-producer / single-consumer queue with a fixed capacity and no
// heap: the hand-over between block preparation (one thread) and the cyclic
// kernel (another thread, or the same one in a dry run).
//
// Threading contract: exactly one thread calls the producer functions
// (push, free_slots) and exactly one thread calls the consumer functions
// (front, pop, empty, size); they may be different threads. Every function
// is lock-free, noexcept and allocation-free. An element becomes visible to
// the consumer only after push has written it completely (release/acquire
// on the indices), and its slot is reused only after the consumer popped it.
#include <array>
#include <atomic>
#include <cstddef>

namespace nck {

template <class T, std::size_t N>
class SpscQueue {
  static_assert(N > 0, "an SPSC queue needs at least one slot");

 public:
  static constexpr std::size_t capacity() noexcept { return N; }

  // producer: false when full (nothing is written).
  bool push(const T& v) noexcept {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail - head_.load(std::memory_order_acquire) >= N) return false;
    items_[tail % N] = v;
    tail_.store(tail + 1, std::memory_order_release);
    return true;
  }
  // producer: slots that are surely free (more may free up meanwhile).
  std::size_t free_slots() const noexcept {
    return N - (tail_.load(std::memory_order_relaxed) - head_.load(std::memory_order_acquire));
  }

  // consumer
  bool empty() const noexcept {
    return head_.load(std::memory_order_relaxed) == tail_.load(std::memory_order_acquire);
  }
  std::size_t size() const noexcept {
    return tail_.load(std::memory_order_acquire) - head_.load(std::memory_order_relaxed);
  }
  // consumer: the oldest element; only while !empty().
  const T& front() const noexcept { return items_[head_.load(std::memory_order_relaxed) % N]; }
  // consumer: the i-th oldest element (0 = front); only while i < size().
  const T& at(std::size_t i) const noexcept { return items_[(head_.load(std::memory_order_relaxed) + i) % N]; }
  // consumer: drops the oldest element (nothing when empty).
  void pop() noexcept {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    if (head == tail_.load(std::memory_order_acquire)) return;
    head_.store(head + 1, std::memory_order_release);
  }

 private:
  std::array<T, N> items_{};
  // Monotonic counters (wrap-around of size_t is harmless: only differences count).
  alignas(64) std::atomic<std::size_t> head_{0};  // next element to pop
  alignas(64) std::atomic<std::size_t> tail_{0};  // next slot to fill
};

}  // namespace nck
