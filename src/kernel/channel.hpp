#pragma once
// A channel's cyclic executor: takes planned commands from its queue and
// runs each through its phases — outputs and waits before the motion, the
// motion (or dwell), outputs and waits after it — stopping exactly at each
// block end.
//
// Continuous-path blending is not done yet: every block ends at standstill
// (exact stop, like G60). The profile already takes an end velocity, so
// blending will come as a look-ahead in the planner that sets it
// (docs/decisions.md).
#include <string>
#include <vector>

#include "command.hpp"
#include "nck/core/ring_buffer.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/motion/path_profile.hpp"
#include "nck/plc/hli.hpp"
#include "nck/plc/plc_sim.hpp"
#include "measure.hpp"
#include "planner.hpp"
#include "spindle_unit.hpp"

namespace nck::kernel {

inline constexpr std::size_t kQueueLength = 64;
inline constexpr double kHandwheelSpeed_mm_s = 10.0;  // how fast a handwheel offset is travelled

// What a channel reaches besides itself during a cycle.
struct ChannelContext {
  SpindleUnit* spindles = nullptr;  // the machine's spindles, by kernel index
  std::size_t spindle_count = 0;
  plc::PlcSim* plc = nullptr;
  plc::HliImage* hli = nullptr;
};

class Channel {
 public:
  Channel(const config::Machine& machine, std::size_t index, PlanStore& store,
          const PlannerOptions& options, std::vector<std::int8_t> spindles);

  // setup side
  // Blocks that fit: one block may plan into up to 4 commands (G74 homing).
  std::size_t queue_space() const {
    const std::size_t free = queue_.capacity() - queue_.size();
    return free >= 4 ? free - 3 : 0;
  }
  bool push(const Command& c) { return queue_.push(c); }
  Planner& planner() { return planner_; }
  const Planner& planner() const { return planner_; }

  // real-time side
  void tick(double t_s, double dt_s, const ChannelInput& in, ChannelOutput& out,
            TickOutput& sink, ChannelContext& ctx) noexcept;
  // The PLC acknowledged output h (called before tick).
  void on_ack(plc::OutputHandle h) noexcept;

  ChannelStatus status() const noexcept { return status_; }
  bool done() const noexcept {
    return status_ == ChannelStatus::ended || status_ == ChannelStatus::aborted;
  }
  // The path's set point (what the program commanded) and the machine set
  // point (plus the handwheel's manual offset).
  const motion::AxisVector& position() const noexcept { return pos_; }
  motion::AxisVector machine_position() const noexcept;
  const motion::AxisVector& manual_offsets() const noexcept { return manual_mm_; }
  // Points where the decoder must wait for values from execution: finished
  // G100 runs and executed #GET MANUAL OFFSETS blocks.
  std::uint64_t sync_count() const noexcept { return measure_.count + manual_fetches_; }
  bool last_sync_was_measure() const noexcept { return last_sync_measure_; }
  // A handwheel turned by mm on axis j: moves it while it is in manual mode (G201). rt
  void handwheel(std::int8_t axis, double mm) noexcept;
  std::uint8_t number() const noexcept { return number_; }

 private:
  enum class Phase : std::uint8_t { pre_wait, body, post_wait };

  // One thing the channel waits for: a spindle state, a PLC acknowledgement, or both.
  struct Wait {
    std::int8_t spindle = -1;
    SpindleWait what = SpindleWait::none;
    plc::OutputHandle handle = plc::kNoHandle;
    bool acked = false;
    double deadline_s = 0;  // 0 = no timeout
    SyncPoint when = SyncPoint::before;
    FunctionKind fn = FunctionKind::none;
    std::int32_t fn_number = 0;
    bool announced = false;
    WaitReason reason = WaitReason::plc_ack;  // as last announced
  };

  void start(const Command& c, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void advance(double t_s, double dt_s, const ChannelInput& in, TickOutput& sink,
               ChannelContext& ctx) noexcept;
  void execute(double dt_s, const ChannelInput& in) noexcept;
  void place(double s_mm) noexcept;
  bool probe_switched(const motion::AxisVector& before) noexcept;
  void complete(double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void finish(EndReason reason, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void raise(ErrorId id, std::uint32_t message, double t_s, TickOutput& sink,
             ChannelContext& ctx) noexcept;
  Event event(EventKind k, double t_s) const noexcept;

  // synchronisation (channel_sync.cpp)
  void issue_all(SyncPoint phase, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  bool issue_spindle_actions(SyncPoint phase, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  bool issue_spindle(const SpindleAction& a, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void issue_output(const Output& o, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void add_wait(const Wait& w, SyncPoint sync) noexcept;
  void take_late_waits(SyncPoint which) noexcept;
  bool waits_done(SyncPoint phase, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  bool satisfied(const Wait& w, const ChannelContext& ctx) const noexcept;
  std::int8_t local_index(std::int8_t spindle) const noexcept;

  Planner planner_;
  RingBuffer<Command, kQueueLength> queue_;
  std::uint8_t number_ = 1;
  std::size_t n_axes_ = 0;
  FixedVector<std::int8_t, config::kMaxSpindles> spindles_;  // kernel index per channel spindle
  ChannelStatus status_ = ChannelStatus::idle;
  bool active_ = false;  // `current_` is being executed
  Phase phase_ = Phase::pre_wait;
  std::size_t next_action_ = 0;  // spindle actions of the block issued so far
  Command current_{};
  motion::PathProfile profile_{};
  double dwell_left_s_ = 0;
  double velocity_ = 0;
  motion::AxisVector pos_{};
  FixedVector<Wait, 24> waits_;  // of the current block
  FixedVector<Wait, 16> late_;   // MVS_SLM / MVS_SLP, carried to a later block
  MeasureResult measure_{};
  std::uint64_t manual_fetches_ = 0;
  bool last_sync_measure_ = false;
  std::uint32_t manual_mask_ = 0;     // axes in manual mode (G201)
  motion::AxisVector manual_mm_{};    // handwheel offset reached so far
  motion::AxisVector manual_target_mm_{};
};

}  // namespace nck::kernel
