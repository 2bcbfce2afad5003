#include "nck/serve/live_kernel.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

namespace nck::app::serve {
namespace {

// SCHED_FIFO for the calling thread and locked memory, where the system
// grants them; what was refused, for the one-line warning.
std::string ask_for_realtime() {
  std::string refused;
  sched_param p{};
  p.sched_priority = 80;
  if (const int e = pthread_setschedparam(pthread_self(), SCHED_FIFO, &p); e != 0)
    refused = fmt::format("real-time scheduling (SCHED_FIFO: {})", std::strerror(e));
  if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0)
    refused += fmt::format("{}locked memory (mlockall: {})", refused.empty() ? "" : " and ", std::strerror(errno));
  return refused;
}

}  // namespace

LiveKernel::LiveKernel(std::unique_ptr<sim::DryRun> first, double speed)
    : current_(first.release()), clock_(current_.load()->kernel().cycle_time_s()) {
  clock_.set_speed(speed);
}

LiveKernel::~LiveKernel() {
  stop();
  delete incoming_.exchange(nullptr);
  delete retired_.exchange(nullptr);
  delete current_.exchange(nullptr);
}

std::string LiveKernel::start(bool realtime) {
  std::string warning;
  std::atomic<bool> asked{false};
  thread_ = std::jthread([this, realtime, &warning, &asked](std::stop_token st) {
    // The kernel thread asks for itself; the answer is read once, below.
    if (realtime && clock_.speed() > 0) warning = ask_for_realtime();
    asked.store(true, std::memory_order_release);
    asked.notify_one();
    run(st);
  });
  asked.wait(false, std::memory_order_acquire);
  if (!realtime) return {};
  return warning.empty() ? std::string()
                         : fmt::format("nck serve: warning: {} not granted; cycles may start late (run as root or "
                                       "with CAP_SYS_NICE and a memlock limit)", warning);
}

void LiveKernel::stop() {
  if (!thread_.joinable()) return;
  thread_.request_stop();
  clock_.wake();  // a wait for a distant deadline ends now, not at the deadline
  thread_.join();
}

bool LiveKernel::load(std::unique_ptr<sim::DryRun> next) {
  sim::DryRun* expected = nullptr;
  if (!incoming_.compare_exchange_strong(expected, next.get(), std::memory_order_acq_rel)) return false;
  (void)next.release();  // the kernel owns it now
  clock_.wake();
  return true;
}

std::unique_ptr<sim::DryRun> LiveKernel::take_retired() {
  return std::unique_ptr<sim::DryRun>(retired_.exchange(nullptr, std::memory_order_acq_rel));
}

void LiveKernel::run(std::stop_token stop) noexcept {
  clock_.start();
  while (!stop.stop_requested()) {
    const std::uint32_t cycles = clock_.wait();
    take_incoming();
    sim::DryRun& now = *current_.load(std::memory_order_relaxed);
    const std::uint64_t steps = steps_.load(std::memory_order_acquire);
    const bool paused = paused_.load(std::memory_order_acquire);
    if (paused && steps == steps_done_) {
      publish(now, *out_);
      continue;
    }
    const std::uint32_t n = paused ? 1 : cycles;
    if (paused) ++steps_done_;
    for (std::uint32_t i = 0; i < n && !stop.stop_requested(); ++i) cycle(now);
    publish(now, *out_);
  }
}

// A run the server handed over replaces the current one at a cycle
// boundary; the old one goes back to the server, which ends its
// preparation thread and frees it (never the kernel thread).
void LiveKernel::take_incoming() noexcept {
  sim::DryRun* next = incoming_.load(std::memory_order_acquire);
  if (!next || retired_.load(std::memory_order_acquire)) return;  // the last one not yet collected
  incoming_.store(nullptr, std::memory_order_release);
  // The axes stay homed across runs (a run staged before a G74 was made
  // with the homed state of its time).
  next->carry_homing(*current_.load(std::memory_order_relaxed));
  retired_.store(current_.exchange(next, std::memory_order_acq_rel), std::memory_order_release);
  generation_.fetch_add(1, std::memory_order_acq_rel);
}

void LiveKernel::cycle(sim::DryRun& run) noexcept {
  for (; !actions_.empty(); actions_.pop()) (void)run.machine().operate(actions_.front());
  try {
    run.prepare_live();  // skip levels and sensors for preparation; rethrows its failure
  } catch (...) {
    // Preparation died (out of memory): the kernel runs on with what it has
    // queued and brakes at its end, as for a late preparation.
  }
  run.cycle(*out_);
  const std::uint64_t generation = generation_.load(std::memory_order_relaxed);
  for (const kernel::Event& e : out_->events)
    if (!events_.push(LiveEvent{generation, e})) ++events_lost_;
}

void LiveKernel::publish(const sim::DryRun& run, const kernel::TickOutput& out) noexcept {
  LiveSnapshot& s = snapshots_.back();
  s.generation = generation_.load(std::memory_order_relaxed);
  s.paused = paused_.load(std::memory_order_relaxed);
  s.speed = clock_.speed();
  fill_snapshot(run, out, s);
  s.lateness = clock_.lateness();
  s.events_lost = events_lost_;
  snapshots_.publish();
}

}  // namespace nck::app::serve
