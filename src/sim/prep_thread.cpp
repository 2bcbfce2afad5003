#include "nck/sim/prep_thread.hpp"

#include <algorithm>

#include "nck/prep/planner.hpp"

namespace nck::sim {

PrepThread::PrepThread(std::vector<prep::ChannelPrep>& preps, kernel::Kernel& kernel,
                       const std::array<std::uint32_t, config::kMaxChannels>& skip_masks)
    : preps_(preps), kernel_(kernel) {
  for (std::size_t ch = 0; ch < skip_masks.size(); ++ch) skip_masks_[ch].store(skip_masks[ch], std::memory_order_relaxed);
  thread_ = std::jthread([this](std::stop_token st) { run(st); });  // sees everything above
}

PrepThread::~PrepThread() { stop(); }

void PrepThread::stop() {
  if (!thread_.joinable()) return;
  thread_.request_stop();
  cycles_.fetch_add(1, std::memory_order_release);  // wakes a pass that waits for a cycle
  cycles_.notify_all();
  thread_.join();
}

// An exception ends preparation: the cycle side stops waiting for it and
// rethrows it (DryRun::prepare), as a single-threaded run would have.
void PrepThread::run(std::stop_token stop) {
  try {
    passes(stop);
  } catch (...) {
    failure_ = std::current_exception();
    failed_.store(true, std::memory_order_release);
    caught_up_.store(~std::uint64_t{0}, std::memory_order_release);
    caught_up_.notify_all();
  }
}

void PrepThread::rethrow_failure() const {
  if (failed_.load(std::memory_order_acquire)) std::rethrow_exception(failure_);
}

void PrepThread::passes(std::stop_token stop) {
  while (!stop.stop_requested()) {
    const std::uint64_t seen = cycles_.load(std::memory_order_acquire);
    const std::size_t n = std::min(preps_.size(), config::kMaxChannels);
    for (std::size_t ch = 0; ch < n; ++ch) idle_[ch].store(Idle::busy, std::memory_order_release);
    bool progress = false;
    for (std::size_t ch = 0; ch < n; ++ch) {
      const bool done = done_[ch].load(std::memory_order_acquire);
      preps_[ch].set_skip_mask(skip_masks_[ch].load(std::memory_order_acquire));
      progress = preps_[ch].feed(kernel_.commands(ch), kernel_.feedback(ch), done) || progress;
      if (preps_[ch].planner().technologies().get<prep::DistUnit>().programmed())
        sensor_[ch].store(true, std::memory_order_release);
    }
    if (progress) continue;
    for (std::size_t ch = 0; ch < n; ++ch) {
      const prep::ChannelPrep& p = preps_[ch];
      const Idle why = p.done() ? Idle::done : p.awaiting_feedback() ? Idle::awaiting_feedback : Idle::busy;
      idle_[ch].store(why, std::memory_order_release);
    }
    // Nothing to do until the kernel has run another cycle.
    caught_up_.store(seen + 1, std::memory_order_release);
    caught_up_.notify_all();
    cycles_.wait(seen, std::memory_order_acquire);
  }
}

void PrepThread::cycle_done() noexcept {
  for (std::size_t ch = 0; ch < preps_.size() && ch < done_.size(); ++ch)
    done_[ch].store(kernel_.channel_done(ch), std::memory_order_release);
  cycles_.fetch_add(1, std::memory_order_release);
  cycles_.notify_all();
}

// Could channel ch's preparation still add to what the next cycle sees?
bool PrepThread::may_add(std::size_t ch, std::size_t ahead) const noexcept {
  if (!preps_[ch].has_program() && !preps_[ch].mdi_pending()) return false;
  switch (idle_[ch].load(std::memory_order_acquire)) {
    case Idle::done:  // the whole program is queued
      if (!preps_[ch].mdi_pending()) return false;
      break;
    case Idle::awaiting_feedback:   // until the kernel hands feedback over
      if (kernel_.feedback(ch).free_slots() == kernel::FeedbackQueue::capacity()) return false;
      break;
    case Idle::busy: break;
  }
  return kernel_.commands(ch).size() < ahead;
}

void PrepThread::wait_caught_up(std::size_t ahead) noexcept {
  const std::uint64_t target = cycles_.load(std::memory_order_relaxed) + 1;
  const std::size_t n = std::min(preps_.size(), config::kMaxChannels);
  for (;;) {
    const std::uint64_t now = caught_up_.load(std::memory_order_acquire);
    if (now >= target) return;
    bool wait = false;
    for (std::size_t ch = 0; ch < n && !wait; ++ch) wait = may_add(ch, ahead);
    if (!wait) return;
    caught_up_.wait(now, std::memory_order_acquire);
  }
}

}  // namespace nck::sim
