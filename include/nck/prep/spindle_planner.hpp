#pragma once
// Spindle planning (setup side): turns the spindle words of one decoded block
// into SpindleActions in execution order. The planner runs ahead of the
// cyclic execution, so it keeps its own PLANNED modal state per spindle
// (speed, POS, gear stage) and decides from it which gear stage and which
// synchronisation. Whether the spindle turns is not part of that state:
// the PLC, another channel or a reset may stop or start it in between, so
// whether an S alone changes the running speed is decided at execution
// (SpindleOp::speed).
#include <cstdint>
#include <expected>
#include <optional>
#include <vector>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/core/fixed_vector.hpp"
#include "nck/nc/block.hpp"
#include "nck/prep/kernel_vocabulary.hpp"

namespace nck::prep {

using SpindleActions = FixedVector<SpindleAction, PlannedCommand::kMaxSpindleActions>;

// The modal spindle data of the program, as planned so far.
struct PlannedSpindle {
  std::optional<double> speed_rpm;   // last S / REV (modal, unsigned as programmed)
  double signed_speed_rpm = 0;       // the same with its sign (G63 turns back on a negative S), 0 before any
  std::optional<double> pos_deg;     // last POS / S.POS (modal)
  double pos_shift_deg = 0;          // S.POS_SHIFT (modal, added to every POS)
  std::uint32_t gear_stage = 1;      // 1..6; starts at kenngr.getriebe_stufe
};


class SpindlePlanner {
 public:
  // kernel_index[i]: the kernel spindle index of the channel's spindel[i]
  // (same order as ChannelConfig::spindles; missing or negative = none).
  SpindlePlanner(const config::Machine& m, std::size_t channel_index,
                 std::vector<int> kernel_index);  // setup

  // Plans the spindle part of one block. Actions come out in execution order.
  // On error nothing of the block is taken over into the planned state.
  // The diagnostic carries the block's line (file left empty). // setup
  std::expected<SpindleActions, Diagnostic> plan(const nc::Block& b);

  // Back to the start-up state (no speed, no POS, initial gear stage).
  void reset();

  std::size_t spindle_count() const { return state_.size(); }
  // Planned state of the channel's spindel[i]; i must be < spindle_count().
  const PlannedSpindle& planned(std::size_t i) const { return state_[i]; }

 private:
  // One spindle command being planned: what it addresses and where it goes.
  struct Step {
    const nc::Block& b;
    const nc::SpindleCommand& c;
    const config::ChannelSpindle& sp;
    std::int8_t kernel_spindle;
    bool plc;                // PLC spindle: every function output, PLC acknowledges
    PlannedSpindle& st;      // working copy of the planned state
    SpindleActions& out;
  };
  std::expected<void, Diagnostic> plan_command(const nc::Block& b, const nc::SpindleCommand& c,
                                               std::vector<PlannedSpindle>& st,
                                               SpindleActions& out) const;
  std::expected<void, Diagnostic> plan_gear(Step& s, std::optional<double> speed_rpm) const;
  std::expected<void, Diagnostic> plan_tool(const nc::Block& b, SpindleActions& out) const;
  std::optional<std::size_t> find_spindle(const nc::SpindleCommand& c) const;

  const config::Machine& machine_;
  const config::ChannelConfig* channel_ = nullptr;  // null when channel_index is out of range
  const config::ChannelData* data_ = nullptr;       // tool list, may be absent
  std::vector<int> kernel_index_;
  std::vector<PlannedSpindle> state_;
};

}  // namespace nck::prep
