#pragma once
// Block preparation in a thread of its own (`nck run --prep-thread`; the
// live kernel): it decodes and plans every channel's program into the
// kernel's command queues while the cycles run elsewhere. The two sides
// share only the SPSC queues and the atomics below, never a lock.
//
// The cycle side publishes, after each cycle, the number of cycles run and
// which channels have ended; preparation publishes, after a pass over every
// channel that found nothing to do, the cycle count it had seen then (it
// has caught up with that cycle) and why each channel is idle. A dry run
// (simulated time) waits for that before a cycle in which preparation could
// still change what a channel has queued, so its outputs are those of
// preparing before every cycle in one thread; a real-time kernel never
// waits (its braking reserve covers a late preparation).
#include <array>
#include <atomic>
#include <cstdint>
#include <exception>
#include <thread>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/kernel/kernel.hpp"
#include "nck/prep/channel_prep.hpp"

namespace nck::sim {

class PrepThread {
 public:
  // setup: starts the thread with these block-skip levels; preps and kernel must outlive it.
  PrepThread(std::vector<prep::ChannelPrep>& preps, kernel::Kernel& kernel,
             const std::array<std::uint32_t, config::kMaxChannels>& skip_masks = {});
  ~PrepThread();  // stops and joins
  PrepThread(const PrepThread&) = delete;
  PrepThread& operator=(const PrepThread&) = delete;

  // cycle side, after a cycle: the kernel's cycle count and ended channels.
  void cycle_done() noexcept;
  // cycle side: waits until no channel's preparation could still add to
  // what the next cycle sees: it has caught up with the last cycle, or has
  // planned its whole program, or waits for feedback the kernel has not
  // given yet, or the channel's queue holds at least `ahead` commands.
  void wait_caught_up(std::size_t ahead) noexcept;
  // Channel ch's program has switched 3D distance control on (the sensor is needed).
  bool sensor_wanted(std::size_t ch) const noexcept {
    return ch < sensor_.size() && sensor_[ch].load(std::memory_order_acquire);
  }
  // cycle side: the HLI's block-skip levels of channel ch (decoding reads them).
  void set_skip_mask(std::size_t ch, std::uint32_t mask) noexcept {
    if (ch < skip_masks_.size()) skip_masks_[ch].store(mask, std::memory_order_release);
  }
  // New work that is not a cycle (MDI text): preparation looks again, and
  // the next wait_caught_up() waits for it.
  void wake() noexcept {
    cycles_.fetch_add(1, std::memory_order_release);
    cycles_.notify_all();
  }
  // Stops the thread; afterwards the preparations may be read from this thread.
  void stop();
  // cycle side: rethrows what ended preparation, if an exception did.
  void rethrow_failure() const;

 private:
  enum class Idle : std::uint8_t { busy, done, awaiting_feedback };
  void run(std::stop_token stop);
  void passes(std::stop_token stop);
  bool may_add(std::size_t ch, std::size_t ahead) const noexcept;

  std::vector<prep::ChannelPrep>& preps_;
  kernel::Kernel& kernel_;
  std::atomic<std::uint64_t> cycles_{0};     // published by the cycle side
  std::atomic<std::uint64_t> caught_up_{0};  // published by preparation: 1 + the cycle count caught up with
  std::array<std::atomic<bool>, config::kMaxChannels> done_{};    // channel ended (cycle side)
  std::array<std::atomic<bool>, config::kMaxChannels> sensor_{};  // #DIST CTRL programmed (preparation)
  std::array<std::atomic<Idle>, config::kMaxChannels> idle_{};   // why preparation waits (preparation)
  std::array<std::atomic<std::uint32_t>, config::kMaxChannels> skip_masks_{};  // HLI skip levels (cycle side)
  std::exception_ptr failure_;  // written before failed_ is set
  std::atomic<bool> failed_{false};
  std::jthread thread_;  // started by the constructor once everything above is set
};

}  // namespace nck::sim
