#pragma once
// The live kernel's clock: absolute deadlines on CLOCK_MONOTONIC, one cycle
// time apart at real time (speed 1), closer at speed N; below a quarter
// millisecond several cycles share a wake-up, so that faster speeds do not
// turn into a sleep per cycle. Lateness — how long after its deadline the
// thread woke — is counted per wake-up in a fixed histogram (no heap).
#include <array>
#include <atomic>
#include <cstdint>
#include <ctime>

#include "nck/serve/live_snapshot.hpp"

namespace nck::app::serve {

class CycleClock {
 public:
  explicit CycleClock(double cycle_s) : cycle_ns_(static_cast<std::int64_t>(cycle_s * 1e9)) {}
  // any thread: simulated seconds per wall second, 0 = as fast as possible.
  void set_speed(double speed) noexcept { speed_.store(speed, std::memory_order_release); }
  double speed() const noexcept { return speed_.load(std::memory_order_acquire); }

  // kernel thread: starts the deadlines now.
  void start() noexcept;
  // kernel thread: sleeps until the next deadline and returns how many
  // cycles to run now (at speed 0 without sleeping).
  std::uint32_t wait() noexcept;
  // kernel thread: the lateness so far (percentiles refreshed about once a second).
  const Lateness& lateness() noexcept;

 private:
  static constexpr std::size_t kBuckets = 10000;  // 1 µs each; the last holds everything later
  void record(std::int64_t late_ns) noexcept;

  std::int64_t cycle_ns_;
  std::atomic<double> speed_{1.0};
  timespec deadline_{};
  std::array<std::uint32_t, kBuckets> histogram_us_{};
  std::uint64_t recorded_ = 0;
  std::uint64_t refreshed_at_ = 0;
  Lateness lateness_;
};

}  // namespace nck::app::serve
