#pragma once
// A FIFO with a fixed capacity and no heap: the queue between the (non-RT)
// block preparation and the (RT) cyclic execution.
#include <array>
#include <cstddef>

namespace nck {

template <class T, std::size_t N>
class RingBuffer {
 public:
  constexpr std::size_t size() const noexcept { return size_; }
  static constexpr std::size_t capacity() noexcept { return N; }
  constexpr bool empty() const noexcept { return size_ == 0; }
  constexpr bool full() const noexcept { return size_ == N; }
  constexpr bool push(const T& v) noexcept {
    if (full()) return false;
    items_[(head_ + size_) % N] = v;
    ++size_;
    return true;
  }
  constexpr T& front() noexcept { return items_[head_]; }
  constexpr const T& front() const noexcept { return items_[head_]; }
  // i-th element from the front, i < size().
  constexpr const T& at(std::size_t i) const noexcept { return items_[(head_ + i) % N]; }
  constexpr void pop() noexcept {
    if (empty()) return;
    head_ = (head_ + 1) % N;
    --size_;
  }
  constexpr void clear() noexcept { head_ = size_ = 0; }

 private:
  std::array<T, N> items_{};
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

}  // namespace nck
