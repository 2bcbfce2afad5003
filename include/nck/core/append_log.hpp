#pragma once
// An append-only sequence that one thread appends to while other threads
// read what was appended before: texts and values that events refer to by
// index, written by block preparation (its own thread, or the run's) and
// read when the events are written out.
//
// Elements never move: they live in chunks of doubling size (64, 128, 256
// ...), found from the index by arithmetic; a directory of 40 chunk
// pointers covers more elements than memory holds. The count is published
// with release/acquire, so a reader sees an element completely once the
// count includes it. Appending allocates (setup side); reading never does.
#include <array>
#include <atomic>
#include <bit>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <utility>

namespace nck {

template <class T>
class AppendLog {
 public:
  AppendLog() = default;
  AppendLog(const AppendLog&) = delete;
  AppendLog& operator=(const AppendLog&) = delete;

  // writer: appends v and returns its index.
  std::size_t push_back(T v) {
    const std::size_t i = size_.load(std::memory_order_relaxed);
    const auto [chunk, offset] = locate(i);
    if (!chunks_[chunk]) chunks_[chunk] = std::make_unique<T[]>(kFirstChunk << chunk);
    chunks_[chunk][offset] = std::move(v);
    size_.store(i + 1, std::memory_order_release);
    return i;
  }
  // any thread: elements appended so far.
  std::size_t size() const noexcept { return size_.load(std::memory_order_acquire); }
  bool empty() const noexcept { return size() == 0; }
  // any thread: element i, or std::out_of_range (setup side, tests).
  const T& at(std::size_t i) const {
    if (i >= size()) throw std::out_of_range("AppendLog::at");
    return (*this)[i];
  }
  // any thread: element i, for i < size().
  const T& operator[](std::size_t i) const noexcept {
    const auto [chunk, offset] = locate(i);
    return chunks_[chunk][offset];
  }

 private:
  static constexpr std::size_t kFirstChunk = 64;
  static constexpr std::size_t kChunks = 40;

  // Chunk c holds the indices kFirstChunk * (2^c - 1) ... kFirstChunk * (2^(c+1) - 1) - 1.
  static std::pair<std::size_t, std::size_t> locate(std::size_t i) noexcept {
    const std::size_t chunk = static_cast<std::size_t>(std::bit_width(i / kFirstChunk + 1)) - 1;
    return {chunk, i - kFirstChunk * ((std::size_t{1} << chunk) - 1)};
  }

  std::array<std::unique_ptr<T[]>, kChunks> chunks_{};
  std::atomic<std::size_t> size_{0};
};

}  // namespace nck
