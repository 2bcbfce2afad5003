#pragma once
// Synchronisation of a block's spindle and PLC functions with its motion
// (FCT-S1 2.5): what is output when, and what the channel waits for before
// and after the block's motion. This unit reads a command's outputs,
// spindle_actions, feed_motion and expl_syn.
#include <cstddef>
#include <cstdint>

#include "nck/kernel/command.hpp"
#include "cycle.hpp"

namespace nck::kernel {

class SyncUnit {
 public:
  // At a block's start: late functions (MVS_SLM / MVS_SLP) carried from
  // earlier blocks synchronise before this block's motion. rt
  void take_late_waits(const Command& c) noexcept;
  // Outputs and spindle actions of block c issued in `phase` (before or
  // after the motion). rt
  Fault issue_all(const Command& c, SyncPoint phase, Cycle& cy) noexcept;
  // Issues the spindle actions of `phase` held back behind a gear change. rt
  Fault issue_spindle_actions(const Command& c, SyncPoint phase, Cycle& cy) noexcept;
  // Spindle actions of block c not issued yet (behind a gear change). rt
  bool actions_left(const Command& c) const noexcept { return next_action_ < c.spindle_actions.size(); }
  // Checks the waits of `phase`: announces new ones, ends satisfied ones,
  // and returns a timeout or a spindle error. rt
  Fault update_waits(SyncPoint phase, Cycle& cy) noexcept;
  // Some wait of `phase` is left. rt
  bool waiting(SyncPoint phase) const noexcept;
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
    FunctionKind fn = FunctionKind::none;
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
  FixedVector<Wait, Command::kMaxOutputs + Command::kMaxSpindleActions + kMaxLateWaits> waits_;
  FixedVector<Wait, kMaxLateWaits> late_;
  std::size_t next_action_ = 0;  // spindle actions of the block issued so far
};

}  // namespace nck::kernel
