#pragma once
// The kernel live (nck serve): a thread of its own runs one cycle per
// absolute deadline (clock_nanosleep), at real time or a chosen speed, with
// preparation in the run's preparation thread. The server thread talks to
// it only through lock-free hand-overs, never a lock the kernel waits on:
//
//   server -> kernel   operator actions (SPSC queue), a new run (atomic
//                      pointer), pause / step / speed (atomics)
//   kernel -> server   the state after each cycle (triple buffer), every
//                      event in order (SPSC queue), the run it retired
//
// One server thread is the only producer and consumer on its side.
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

#include "nck/core/spsc_queue.hpp"
#include "nck/core/triple_buffer.hpp"
#include "nck/serve/cycle_clock.hpp"
#include "nck/serve/live_snapshot.hpp"
#include "nck/sim/dry_run.hpp"

namespace nck::app::serve {

// An event with the run it belongs to (its texts live in that run).
struct LiveEvent {
  std::uint64_t generation = 0;
  kernel::Event event;
};

class LiveKernel {
 public:
  static constexpr std::size_t kActionSlots = 64;
  static constexpr std::size_t kEventSlots = 16384;

  // setup: `first` is the run to start with (it may have no program).
  LiveKernel(std::unique_ptr<sim::DryRun> first, double speed);
  ~LiveKernel();  // stops the thread
  LiveKernel(const LiveKernel&) = delete;
  LiveKernel& operator=(const LiveKernel&) = delete;

  // Starts the kernel thread; the one-line warning when real-time
  // scheduling or locked memory was not granted (empty: granted).
  std::string start(bool realtime);
  void stop();

  // server thread ------------------------------------------------------
  // Hands a new run over; the kernel takes it at its next cycle. false
  // while the one before has not been taken yet.
  bool load(std::unique_ptr<sim::DryRun> next);
  // The run the kernel now runs, once it has taken it, for the server's
  // reads of what preparation owns (MDI, names); and the one it gave back.
  sim::DryRun* current() const noexcept { return current_.load(std::memory_order_acquire); }
  std::unique_ptr<sim::DryRun> take_retired();
  // An operator action for the next cycle; false when the queue is full.
  bool operate(const sim::ScenarioAction& a) noexcept {
    const bool queued = actions_.push(a);
    clock_.wake();  // a slow speed's cycle is seconds away: the action is not
    return queued;
  }
  // The newest state, if one was published since the last call.
  bool take_snapshot() noexcept { return snapshots_.take(); }
  const LiveSnapshot& snapshot() const noexcept { return snapshots_.front(); }
  // Events in the order the kernel emitted them.
  SpscQueue<LiveEvent, kEventSlots>& events() noexcept { return events_; }

  void set_paused(bool on) noexcept {
    paused_.store(on, std::memory_order_release);
    clock_.wake();
  }
  void step_one_cycle() noexcept {
    steps_.fetch_add(1, std::memory_order_acq_rel);
    clock_.wake();
  }
  // Simulated seconds per wall second; 0 runs as fast as the machine can.
  void set_speed(double speed) noexcept { clock_.set_speed(speed); }

 private:
  void run(std::stop_token stop) noexcept;
  void cycle(sim::DryRun& run) noexcept;
  void publish(const sim::DryRun& run, const kernel::TickOutput& out) noexcept;
  void take_incoming() noexcept;

  std::atomic<sim::DryRun*> current_;
  std::atomic<sim::DryRun*> incoming_{nullptr};
  std::atomic<sim::DryRun*> retired_{nullptr};
  std::atomic<std::uint64_t> generation_{1};
  SpscQueue<sim::ScenarioAction, kActionSlots> actions_;
  SpscQueue<LiveEvent, kEventSlots> events_;
  TripleBuffer<LiveSnapshot> snapshots_;
  std::unique_ptr<kernel::TickOutput> out_ = std::make_unique<kernel::TickOutput>();
  CycleClock clock_;
  std::atomic<bool> paused_{false};
  std::atomic<std::uint64_t> steps_{0};
  std::uint64_t steps_done_ = 0;
  std::uint64_t events_lost_ = 0;
  std::jthread thread_;  // last: started by start()
};

}  // namespace nck::app::serve
