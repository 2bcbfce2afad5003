#pragma once
// A vector with a fixed capacity and no heap: safe in the cyclic path.
//
// The slots beyond size() are raw storage: neither initialised nor copied,
// so a large capacity costs nothing until it is used (a planned block of
// four commands used to be value-initialised and copied whole, 13.5 KB).
#include <cstddef>
#include <cstring>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace nck {

template <class T, std::size_t N>
class FixedVector {
 public:
  FixedVector() noexcept {}
  FixedVector(const FixedVector& o) noexcept(std::is_nothrow_copy_constructible_v<T>) { append(o); }
  FixedVector& operator=(const FixedVector& o) noexcept(std::is_nothrow_copy_constructible_v<T>) {
    if (this != &o) {
      clear();
      append(o);
    }
    return *this;
  }
  ~FixedVector() { clear(); }

  std::size_t size() const noexcept { return size_; }
  static constexpr std::size_t capacity() noexcept { return N; }
  bool empty() const noexcept { return size_ == 0; }
  bool full() const noexcept { return size_ == N; }
  bool push_back(const T& v) noexcept(std::is_nothrow_copy_constructible_v<T>) {
    if (size_ == N) return false;
    std::construct_at(slot(size_), v);
    ++size_;
    return true;
  }
  // Constructs an element in place: nullptr when full.
  template <class... Args>
  T* emplace_back(Args&&... args) noexcept(std::is_nothrow_constructible_v<T, Args...>) {
    if (size_ == N) return nullptr;
    T* p = std::construct_at(slot(size_), std::forward<Args>(args)...);
    ++size_;
    return p;
  }
  void pop_back() noexcept {
    if (size_ == 0) return;
    --size_;
    std::destroy_at(slot(size_));
  }
  void clear() noexcept {
    std::destroy_n(begin(), size_);
    size_ = 0;
  }
  T& operator[](std::size_t i) noexcept { return *slot(i); }
  const T& operator[](std::size_t i) const noexcept { return *slot(i); }
  T& back() noexcept { return *slot(size_ - 1); }
  T* begin() noexcept { return slot(0); }
  T* end() noexcept { return slot(size_); }
  const T* begin() const noexcept { return slot(0); }
  const T* end() const noexcept { return slot(size_); }

 private:
  void append(const FixedVector& o) noexcept(std::is_nothrow_copy_constructible_v<T>) {
    if constexpr (std::is_trivially_copyable_v<T>) {
      if (o.size_ > 0) std::memcpy(static_cast<void*>(storage_), o.storage_, o.size_ * sizeof(T));
      size_ = o.size_;
    } else {
      for (const T& v : o) (void)push_back(v);
    }
  }
  T* slot(std::size_t i) noexcept { return std::launder(reinterpret_cast<T*>(storage_)) + i; }
  const T* slot(std::size_t i) const noexcept {
    return std::launder(reinterpret_cast<const T*>(storage_)) + i;
  }

  alignas(T) std::byte storage_[N * sizeof(T)];
  std::size_t size_ = 0;
};

}  // namespace nck
