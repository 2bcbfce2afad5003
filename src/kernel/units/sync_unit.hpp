#pragma once
// Synchronisation of a block's spindle and PLC functions with its motion
// (FCT-S1 2.5): what is output when, and what the channel waits for before
// and after the block's motion. This unit takes a block's Output and
// SpindleAction attachments, and reads its feed_motion and expl_syn.
#include <cstddef>
#include <cstdint>

#include "nck/kernel/attachment.hpp"
#include "nck/kernel/command.hpp"
#include "cycle.hpp"

namespace nck::kernel {

class SyncUnit {
 public:
  // At a block's start: late functions (MVS_SLM / MVS_SLP) carried from
  // earlier blocks synchronise before this block's motion; the block's
  // outputs and spindle actions follow (take), in their order. rt
  void start_block(const Command& c) noexcept;
  void take(const Output& o) noexcept { (void)outputs_.push_back(o); }
  void take(const SpindleAction& a) noexcept { (void)actions_.push_back(a); }
  // Outputs and spindle actions of the block issued in `phase` (before or
  // after the motion). rt
  Fault issue_all(SyncPoint phase, Cycle& cy) noexcept;
  // Issues the spindle actions of `phase` held back behind a gear change. rt
  Fault issue_spindle_actions(SyncPoint phase, Cycle& cy) noexcept;
  // The block outputs functions or commands spindles (single step holds after it).
  bool has_functions() const noexcept { return !outputs_.empty() || !actions_.empty(); }
  // Spindle actions of the block not issued yet (behind a gear change). rt
  bool actions_left() const noexcept { return next_action_ < actions_.size(); }
  // Checks the waits of `phase`: announces new ones, ends satisfied ones,
  // and returns a timeout or a spindle error. rt
  Fault update_waits(SyncPoint phase, Cycle& cy) noexcept;
  // Some wait of `phase` is left. rt
  bool waiting(SyncPoint phase) const noexcept;
  // What the first wait of `phase` waits for (time by cause). rt
  WaitReason reason(SyncPoint phase) const noexcept;
  // The PLC acknowledged output h. rt
  void on_ack(plc::OutputHandle h) noexcept;
  // Program end: nothing to wait for. rt
  void clear() noexcept {
    waits_.clear();
    late_.clear();
  }

 private:
  // One thing the channel waits for: a spindle state, a PLC acknowledgement, or both.
  struct Wait {
    std::int8_t spindle = -1;
    SpindleWait what = SpindleWait::none;
    plc::OutputHandle handle = plc::kNoHandle;
    bool acked = false;
    double deadline_s = 0;  // 0 = no timeout
    SyncPoint when = SyncPoint::before;
    plc::TechKind fn = plc::TechKind::none;
    std::int32_t fn_number = 0;
    bool announced = false;
    WaitReason reason = WaitReason::plc_ack;  // as last announced
  };

  Fault issue_spindle(const SpindleAction& a, Cycle& cy) noexcept;
  Fault output_spindle_function(const SpindleAction& a, const SpindleAction& now, Wait& w, Cycle& cy) noexcept;
  Fault issue_output(const Output& o, Cycle& cy) noexcept;
  bool add_wait(const Wait& w, SyncPoint sync) noexcept;
  void take_late_waits(SyncPoint which) noexcept;
  Fault check(Wait& w, bool& stays, Cycle& cy) noexcept;

  // Every output and spindle action of a block may wait once, and the late
  // waits (MVS_SLM / MVS_SLP) carried from earlier blocks join them; late
  // waits beyond kMaxLateWaits raise KernelWaitOverflow.
  static constexpr std::size_t kMaxLateWaits = 16;
  FixedVector<Output, kMaxOutputs> outputs_;                // of the block
  FixedVector<SpindleAction, kMaxSpindleActions> actions_;  // of the block
  FixedVector<Wait, kMaxOutputs + kMaxSpindleActions + kMaxLateWaits> waits_;
  FixedVector<Wait, kMaxLateWaits> late_;
  std::size_t next_action_ = 0;  // spindle actions of the block issued so far
};

}  // namespace nck::kernel
