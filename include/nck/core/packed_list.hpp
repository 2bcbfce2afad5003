#pragma once
// Up to N values in place, itself trivially copyable when T is: for data
// that crosses the real-time queues (which may live in shared memory) as
// plain bytes. FixedVector keeps only its live elements; this copies all N.
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace nck {

template <class T, std::size_t N>
class PackedList {
  static_assert(std::is_trivially_copyable_v<T> && N <= 255);

 public:
  bool push_back(const T& v) noexcept {
    if (size_ == N) return false;
    items_[size_++] = v;
    return true;
  }
  std::size_t size() const noexcept { return size_; }
  bool empty() const noexcept { return size_ == 0; }
  const T& operator[](std::size_t i) const noexcept { return items_[i]; }
  const T* begin() const noexcept { return items_.data(); }
  const T* end() const noexcept { return items_.data() + size_; }

 private:
  std::array<T, N> items_{};
  std::uint8_t size_ = 0;
};

}  // namespace nck
