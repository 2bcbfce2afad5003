#pragma once
// A channel's cyclic executor: takes planned commands from its queue and
// runs them one after the other, stopping exactly at each block end.
//
// Continuous-path blending is not done yet: every block ends at standstill
// (exact stop, like G60). The profile already takes an end velocity, so
// blending will come as a look-ahead in the planner that sets it
// (docs/decisions.md).
#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "nck/core/ring_buffer.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/motion/path_profile.hpp"
#include "planner.hpp"

namespace nck::kernel {

inline constexpr std::size_t kQueueLength = 64;

class Channel {
 public:
  Channel(const config::Machine& machine, std::size_t index, PlanStore& store,
          const PlannerOptions& options);

  // setup side
  std::size_t queue_space() const { return queue_.capacity() - queue_.size(); }
  bool push(const Command& c) { return queue_.push(c); }
  Planner& planner() { return planner_; }
  const Planner& planner() const { return planner_; }

  // real-time side
  void tick(double t_s, double dt_s, const ChannelInput& in, ChannelOutput& out,
            TickOutput& sink) noexcept;

  ChannelStatus status() const noexcept { return status_; }
  bool done() const noexcept {
    return status_ == ChannelStatus::ended || status_ == ChannelStatus::aborted;
  }
  const motion::AxisVector& position() const noexcept { return pos_; }
  std::uint8_t number() const noexcept { return number_; }

 private:
  void start(const Command& c, double t_s, TickOutput& sink) noexcept;
  void execute(double dt_s, const ChannelInput& in) noexcept;
  void place(double s_mm) noexcept;
  void finish(EndReason reason, double t_s, TickOutput& sink) noexcept;
  void emit(TickOutput& sink, const Event& e) noexcept;

  Planner planner_;
  RingBuffer<Command, kQueueLength> queue_;
  std::uint8_t number_ = 1;
  std::size_t n_axes_ = 0;
  ChannelStatus status_ = ChannelStatus::idle;
  bool active_ = false;          // `current_` is being executed
  Command current_{};
  motion::PathProfile profile_{};
  double dwell_left_s_ = 0;
  double velocity_ = 0;
  motion::AxisVector pos_{};
};

}  // namespace nck::kernel
