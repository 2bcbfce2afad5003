#include "nck/serve/cycle_clock.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>

namespace nck::app::serve {
namespace {

constexpr std::int64_t kNsPerS = 1'000'000'000;
constexpr std::int64_t kMinWakeNs = 250'000;  // faster speeds batch cycles per wake-up
constexpr std::uint32_t kMaxSpeedBatch = 1000;  // speed 0: cycles between two looks at the stop flag

std::int64_t to_ns(const timespec& t) { return t.tv_sec * kNsPerS + t.tv_nsec; }
timespec from_ns(std::int64_t ns) { return timespec{static_cast<time_t>(ns / kNsPerS), static_cast<long>(ns % kNsPerS)}; }
std::int64_t now_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return to_ns(t);
}

}  // namespace

void CycleClock::start() noexcept {
  deadline_ = from_ns(now_ns());
  wakes_seen_ = wake_requests_.load(std::memory_order_acquire);  // the setup's (a speed, a pause) are read anyway
}

std::uint32_t CycleClock::wait() noexcept {
  const double speed = speed_.load(std::memory_order_acquire);
  if (!(speed > 0)) {
    deadline_ = from_ns(now_ns());
    wakes_seen_ = wake_requests_.load(std::memory_order_acquire);  // every cycle looks at its actions
    return kMaxSpeedBatch;
  }
  // cycles per wake-up and the wall time they take at this speed (held to
  // the range: 1e-300 overflowed the deadline and ran flat out)
  const double period_ns = static_cast<double>(cycle_ns_) / std::clamp(speed, kMinSpeed, kMaxSpeed);
  const auto batch = static_cast<std::uint32_t>(std::clamp(std::ceil(kMinWakeNs / period_ns), 1.0, 1e6));
  const auto step_ns = static_cast<std::int64_t>(period_ns * batch);
  std::int64_t next = to_ns(deadline_) + step_ns;
  deadline_ = from_ns(next);
  if (!sleep_until(next)) {
    deadline_ = from_ns(now_ns());
    return 1;
  }
  const std::int64_t late_ns = now_ns() - next;
  record(late_ns);
  // A wake-up a second late (a stopped process, a suspended VM) does not
  // make the kernel race to catch up: the deadlines start again from now.
  if (late_ns > kNsPerS) deadline_ = from_ns(now_ns());
  return batch;
}

bool CycleClock::sleep_until(std::int64_t deadline_ns) noexcept {
  for (;;) {
    const std::int64_t now = now_ns();
    if (now >= deadline_ns) return true;
    // The last stretch is slept whole (EINTR: the loop looks again).
    const bool last = deadline_ns - now <= kMaxSleepNs;
    const timespec until = from_ns(last ? deadline_ns : now + kMaxSleepNs);
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &until, nullptr);
    if (last) continue;
    // A request made while the kernel was busy counts too: it may be an
    // action pushed after the cycle took its queue.
    const std::uint64_t requests = wake_requests_.load(std::memory_order_acquire);
    if (requests != wakes_seen_) {
      wakes_seen_ = requests;
      return false;
    }
  }
}

void CycleClock::record(std::int64_t late_ns) noexcept {
  const double late_us = static_cast<double>(std::max<std::int64_t>(late_ns, 0)) / 1e3;
  const auto bucket = std::min<std::size_t>(static_cast<std::size_t>(late_us), kBuckets - 1);
  ++histogram_us_[bucket];
  ++recorded_;
  ++lateness_.wakeups;
  if (late_ns > cycle_ns_) ++lateness_.late_cycles;
  lateness_.worst_us = std::max(lateness_.worst_us, late_us);
}

const Lateness& CycleClock::lateness() noexcept {
  if (recorded_ - refreshed_at_ < 1000) return lateness_;
  refreshed_at_ = recorded_;
  // the bucket in which the running count passes a share of all wake-ups
  const auto percentile = [&](double share) {
    const auto wanted = static_cast<std::uint64_t>(std::ceil(share * static_cast<double>(recorded_)));
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < kBuckets; ++i)
      if ((seen += histogram_us_[i]) >= wanted) return static_cast<double>(i) + 1.0;  // upper edge
    return static_cast<double>(kBuckets);
  };
  lateness_.p50_us = percentile(0.5);
  lateness_.p99_us = percentile(0.99);
  return lateness_;
}

}  // namespace nck::app::serve
