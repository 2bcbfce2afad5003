#pragma once
// A channel's cyclic executor: takes planned commands from its command queue
// and runs each through its phases — outputs and waits before the motion,
// the motion (or dwell), outputs and waits after it — stopping exactly at
// each block end. What preparation needs back (G100 results, handwheel
// offsets) leaves through the feedback queue.
//
// Continuous path: a motion ends at the velocity the look-ahead planned
// (Command::v_end_mm_s, 0 = exact stop). When it ends at speed, the next
// block starts within the same cycle and carries on from the distance the
// path ran past the end, so the set points never pause at a transition.
// The look-ahead lets the path pass only into blocks that do not wait;
// preparation must keep the queue filled ahead of such a transition (the
// dry run does: it prepares before every cycle).
#include <string>
#include <vector>

#include "nck/distctrl/controller.hpp"
#include "nck/kernel/command.hpp"
#include "nck/kernel/queues.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/motion/path_profile.hpp"
#include "nck/plc/hli.hpp"
#include "plc_outputs.hpp"
#include "spindle_unit.hpp"

namespace nck::kernel {

inline constexpr double kHandwheelSpeed_mm_s = 10.0;  // how fast a handwheel offset is travelled

// What a channel reaches besides itself during a cycle.
struct ChannelContext {
  SpindleUnit* spindles = nullptr;  // the machine's spindles, by kernel index
  std::size_t spindle_count = 0;
  PlcOutputs* plc = nullptr;
  const std::array<plc::SpindleControl, kMaxMachineSpindles>* spindle_controls = nullptr;
};

class Channel {
 public:
  // setup: spindles holds the kernel spindle index of each channel spindle.
  Channel(std::size_t index, std::size_t n_axes, const std::vector<std::int8_t>& spindles,
          CommandQueue& commands, FeedbackQueue& feedback);

  // real-time side
  void tick(double t_s, double dt_s, const ChannelInput& in, ChannelOutput& out,
            TickOutput& sink, ChannelContext& ctx) noexcept;
  // The PLC acknowledged output h (called before tick).
  void on_ack(plc::OutputHandle h) noexcept;

  ChannelStatus status() const noexcept { return status_; }
  ProgramState program_state() const noexcept { return state_; }
  // An event of kind k at the block the channel stands at.
  Event event(EventKind k, double t_s) const noexcept;
  bool done() const noexcept {
    return status_ == ChannelStatus::ended || status_ == ChannelStatus::aborted;
  }
  // The path's set point (what the program commanded) and the machine set
  // point (plus the handwheel's manual offset).
  const motion::AxisVector& position() const noexcept { return pos_; }
  motion::AxisVector machine_position() const noexcept;
  // The handwheel offset in the set point now (less than travelled while
  // #SUPPRESS OFFSETS or #MCS leaves it out).
  const motion::AxisVector& manual_offsets() const noexcept { return manual_in_force_mm_; }
  std::uint8_t number() const noexcept { return number_; }
  // setup: channel axis `axis` is spindle `spindle` (kernel index) in
  // C-axis mode (#CAX); outside it the axis shows the spindle's position.
  void set_c_axis(std::int8_t axis, std::int8_t spindle) noexcept;
  // setup: P-CHAN-00105, enabled couplings survive M30 / M2.
  void set_preserve_links(bool on) noexcept { preserve_links_ = on; }
  // The enabled coupling groups' plan-store payloads, in enabling order.
  template <class F>
  void for_each_link(F&& f) const {
    for (const ActiveLink& l : links_) f(l.cmd.payload);
  }
  // setup: 3D distance control's settings (dist_ctrl[0]) and cycle time.
  void set_dist_ctrl(const distctrl::Settings& s, double dt_s) noexcept;
  distctrl::State dist_state() const noexcept { return dist_.state(); }
  double dist_offset_mm() const noexcept { return dist_.offset_mm(); }

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
  void execute(double t_s, double dt_s, const ChannelInput& in, TickOutput& sink, ChannelContext& ctx) noexcept;
  void place(double s_mm) noexcept;
  void keep_braking_reserve(double dt_s) noexcept;
  void note_starved(double t_s, TickOutput& sink) noexcept;
  void dwell_revolutions(double t_s, double dt_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void end_measuring_run(double t_s, const ChannelInput& in, TickOutput& sink, ChannelContext& ctx) noexcept;
  void send_feedback(const Feedback& f, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void follow_handwheel(double t_s, double dt_s, const ChannelInput& in, TickOutput& sink,
                        ChannelContext& ctx) noexcept;
  void end_block(double t_s, const ChannelInput& in, TickOutput& sink, ChannelContext& ctx) noexcept;
  void end_program(EndReason reason, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void raise(ErrorId id, std::uint32_t message, double t_s, TickOutput& sink,
             ChannelContext& ctx) noexcept;
  // Enters program state `to` (a `state` event when it changes).
  void set_state(ProgramState to, StateReason why, double t_s, TickOutput& sink) noexcept;
  // A programmed stop that applies holds the channel until cycle start.
  void stop_program(const ChannelInput& in, double t_s, TickOutput& sink) noexcept;

  // synchronisation (channel_sync.cpp)
  void issue_all(SyncPoint phase, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  bool issue_spindle_actions(SyncPoint phase, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  bool issue_spindle(const SpindleAction& a, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void issue_output(const Output& o, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  bool add_wait(const Wait& w, SyncPoint sync) noexcept;
  void take_late_waits(SyncPoint which) noexcept;
  bool waits_done(SyncPoint phase, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  bool satisfied(const Wait& w, const ChannelContext& ctx) const noexcept;
  std::int8_t local_index(std::int8_t spindle) const noexcept;

  CommandQueue* commands_ = nullptr;
  FeedbackQueue* feedback_ = nullptr;
  std::uint8_t number_ = 1;
  std::size_t n_axes_ = 0;
  FixedVector<std::int8_t, config::kMaxSpindles> spindles_;  // kernel index per channel spindle
  ChannelStatus status_ = ChannelStatus::idle;
  ProgramState state_ = ProgramState::idle;
  bool active_ = false;  // `current_` is being executed
  Phase phase_ = Phase::pre_wait;
  std::size_t next_action_ = 0;  // spindle actions of the block issued so far
  Command current_{};
  motion::PathProfile profile_{};
  double dwell_left_s_ = 0;
  double dwell_revs_left_ = 0;
  double velocity_ = 0;
  bool passing_ = false;  // the last motion ended at speed: the next one takes over this cycle
  bool reserve_ = false;  // the motion's end speed is lowered: its successors are not all queued yet
  bool starved_ = false;  // the braking reserve slowed the path (a KernelPrepStarved episode)
  bool moved_this_cycle_ = false, moved_last_cycle_ = false;  // the path advanced in this / the last cycle
  motion::AxisVector pos_{};
  // Every output and spindle action of a block may wait once, and the late
  // waits (MVS_SLM / MVS_SLP) carried from earlier blocks join them; late
  // waits beyond kMaxLateWaits raise KernelWaitOverflow.
  static constexpr std::size_t kMaxLateWaits = 16;
  FixedVector<Wait, Command::kMaxOutputs + Command::kMaxSpindleActions + kMaxLateWaits> waits_;
  FixedVector<Wait, kMaxLateWaits> late_;
  bool probe_armed_ = false;           // the G100 run has moved: a probe switch is its own
  bool awaiting_probe_ = false;        // G100 reached its end point: one more cycle for the probe
  bool manual_fetch_pending_ = false;  // #GET MANUAL OFFSETS: send them at the end of this cycle
  std::uint32_t manual_mask_ = 0;     // axes in manual mode (G201)
  bool handwheel_used_ = false;       // some axis was in manual mode in this run
  motion::AxisVector manual_mm_{};    // handwheel offset reached so far
  motion::AxisVector manual_target_mm_{};
  // Share (0..1) of the handwheel offset in each set point, when the block
  // started and now; blended along a motion block's path so nothing jumps.
  motion::AxisVector manual_share_start_{}, manual_share_{};
  motion::AxisVector manual_in_force_mm_{};
  void take_manual_share(double fraction) noexcept;
  // C-axis machining (channel_cax.cpp)
  bool start_c_axis(const Command& c, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void follow_c_axis(double dt_s, ChannelContext& ctx) noexcept;
  void end_c_axis(ChannelContext& ctx) noexcept;
  std::int8_t c_axis_ = -1;        // channel index of the C axis, -1 none
  std::int8_t c_spindle_ = -1;     // its spindle (kernel index)
  bool c_axis_on_ = false;         // #CAX in force: the path drives the spindle
  double c_last_deg_ = 0;          // C set point of the cycle before (for its velocity)

  // 3D distance control (channel_dist.cpp)
  bool take_dist(const Command& c, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void run_dist(double t_s, const ChannelInput& in, TickOutput& sink, ChannelContext& ctx) noexcept;
  void note_dist_state(double t_s, TickOutput& sink) noexcept;
  bool dist_wind_down() noexcept;
  void dist_output(ChannelOutput& out) const noexcept;
  distctrl::Controller dist_;
  distctrl::State dist_reported_ = distctrl::State::inactive;
  std::int8_t dist_axis_ = -1;     // tool axis carrying the offset
  bool dist_check_sw_ = false;
  std::int8_t dist_source_ = 0;    // 0 the sensor in TickInput, 1 the variable dist_var_
  std::array<char, 32> dist_var_{};
  double dist_sw_neg_mm_ = 0, dist_sw_pos_mm_ = 0;

  // spindle-path couplings (channel_links.cpp)
  SpindleUnit* link_spindle(std::int8_t s, ChannelContext& ctx) const noexcept;
  void take_links(const Command& c, ChannelContext& ctx) noexcept;
  void release_tap_spindle(ChannelContext& ctx) noexcept;
  bool start_links(double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void limit_path(ChannelContext& ctx) noexcept;
  void follow_path(double s_mm, double v_mm_s, ChannelContext& ctx) noexcept;
  void follow_css(ChannelContext& ctx) noexcept;
  std::int8_t tap_spindle_ = -1;   // the spindle tracking the path (G63/G331/G332), -1 none
  double tap_start_deg_ = 0;       // its set point when the block's motion began
  bool thread_waiting_ = false;    // G33: the path waits for the start angle
  double thread_last_deg_ = 0;     // the spindle's set point one cycle ago
  CssLink css_{};                  // G96 in force

  // synchronous operation (channel_axlink.cpp)
  struct ActiveLink {
    LinkCommand cmd{};
    std::array<double, kMaxLinkPairs> base_slave_mm{}, base_master_mm{};  // path-axis pairs
  };
  bool take_ax_link(const Command& c, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void dissolve_link(std::size_t i, LinkReason why, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  void dissolve_links(EndReason end, double t_s, TickOutput& sink, ChannelContext& ctx) noexcept;
  bool linked_elsewhere(std::int8_t spindle, const ChannelContext& ctx) const noexcept;
  void follow_axis_links() noexcept;
  FixedVector<ActiveLink, kMaxLinkGroupNr + 1> links_;
  bool preserve_links_ = false;
};

}  // namespace nck::kernel
