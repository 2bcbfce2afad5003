#pragma once
// The live kernel's clock: absolute deadlines on CLOCK_MONOTONIC, one cycle
// time apart at real time (speed 1), closer at speed N; below a quarter
// millisecond several cycles share a wake-up, so that faster speeds do not
// turn into a sleep per cycle. Lateness — how long after its deadline the
// thread woke — is counted per wake-up in a fixed histogram (no heap).
//
// No sleep is longer than kMaxSleepNs: a wait for a distant deadline (a
// slow speed: 1 s per cycle at 1e-3) sleeps in slices and ends early when
// another thread called wake() (an operator action, a new speed, a stop),
// so that nothing waits for the deadline. The last slice before a
// deadline is never cut short: at real time an action changes no
// deadline.
#include <array>
#include <atomic>
#include <cstdint>
#include <ctime>

#include "nck/serve/live_snapshot.hpp"
#include "nck/serve/speed_range.hpp"

namespace nck::app::serve {

class CycleClock {
 public:
  explicit CycleClock(double cycle_s) : cycle_ns_(static_cast<std::int64_t>(cycle_s * 1e9)) {}
  // The longest sleep: how late a wake() may be seen.
  static constexpr std::int64_t kMaxSleepNs = 10'000'000;

  // any thread: simulated seconds per wall second, 0 = as fast as possible;
  // others are held to kMinSpeed..kMaxSpeed (the API and the command line
  // refuse them before).
  void set_speed(double speed) noexcept {
    speed_.store(speed, std::memory_order_release);
    wake();
  }
  double speed() const noexcept { return speed_.load(std::memory_order_acquire); }
  // any thread: the kernel has something to do before the next deadline;
  // a wait that has more than kMaxSleepNs left ends within kMaxSleepNs.
  void wake() noexcept { wake_requests_.fetch_add(1, std::memory_order_acq_rel); }

  // kernel thread: starts the deadlines now.
  void start() noexcept;
  // kernel thread: sleeps until the next deadline and returns how many
  // cycles to run now (at speed 0 without sleeping); after a wake() it
  // returns 1 early and the deadlines start again from now.
  std::uint32_t wait() noexcept;
  // kernel thread: the lateness so far (percentiles refreshed about once a second).
  const Lateness& lateness() noexcept;

 private:
  static constexpr std::size_t kBuckets = 10000;  // 1 µs each; the last holds everything later
  void record(std::int64_t late_ns) noexcept;
  // Sleeps until `deadline_ns`; false when a wake() cut it short.
  bool sleep_until(std::int64_t deadline_ns) noexcept;

  std::int64_t cycle_ns_;
  std::atomic<double> speed_{1.0};
  std::atomic<std::uint64_t> wake_requests_{0};
  std::uint64_t wakes_seen_ = 0;  // kernel thread
  timespec deadline_{};
  std::array<std::uint32_t, kBuckets> histogram_us_{};
  std::uint64_t recorded_ = 0;
  std::uint64_t refreshed_at_ = 0;
  Lateness lateness_;
};

}  // namespace nck::app::serve
