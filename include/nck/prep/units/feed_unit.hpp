#pragma once
// Feed and the spindle-path feed links (FCT-S1 2.8.6, 2.8.7, 2.8.9; TF5200
// G93-G95, G194): G94 mm/min, G93 block time, G194 share of the maximum, G95
// mm/rev, G33 thread cutting (and its chain), G63 and G331/G332 tapping.
// Preparation only describes the coupling (kernel::FeedLink); the channel
// evaluates it each cycle.
#include <expected>
#include <vector>

#include "nck/prep/spindle_planner.hpp"
#include "nck/prep/units/main_spindle.hpp"
#include "nck/prep/units/plan_context.hpp"

namespace nck::prep {

// The path speed a block asks for.
struct PathSpeed {
  enum class Kind : std::uint8_t {
    programmed,    // `value` mm/s
    axes_max,      // as fast as the axes allow: a coupling sets the speed each cycle
    share_of_max,  // G194: `value` (0..1] of the path's maximum speed
  };
  Kind kind = Kind::programmed;
  double value = 0;
};

class FeedUnit {
 public:
  // spindles: the kernel spindle index of each of the channel's spindles.
  FeedUnit(const config::ChannelConfig& channel, const std::vector<std::int8_t>& spindles);
  const MainSpindle& main_spindle() const { return main_; }

  // What every command of a block carries: the tapping mark (the spindle
  // stays a tracking axis while G63/G331/G332 is modal, G4 included), and
  // the positioning of the spindle when G331 is selected. `main`: the main
  // spindle's planned state after this block's spindle functions.
  PlanResult plan_block(const nc::Block& b, PlannedCommand& c, const PlanContext& ctx, const PlannedSpindle& main);
  // The commanded path speed of a feed block (G1/G2/G3/G33/G63/G331/G332)
  // from `start` to `target` (a coupling goes into c.feed_link).
  std::expected<PathSpeed, Diagnostic> plan_feed(const nc::Block& b, const motion::AxisVector& start,
                                              const motion::AxisVector& target, double length_mm, PlannedCommand& c,
                                              const PlanContext& ctx, const PlannedSpindle& main);

 private:
  PlanResult thread_link(const nc::Block& b, const motion::AxisVector& start, const motion::AxisVector& target,
                         double length_mm, FeedLink& f, const PlanContext& ctx);

  MainSpindle main_;
  nc::Motion prev_motion_ = nc::Motion::rapid;
  int thread_axis_ = 2;           // G33 pitch letter: 0 I (X), 1 J (Y), 2 K (Z)
  double thread_offset_deg_ = 0;  // S.OFFSET, modal to program end
};

}  // namespace nck::prep
