#pragma once
// The path of a channel, its core technology: the velocity profile of the
// motion block that runs, the path set point, and the continuous path
// between blocks (passing into the next block within a cycle, the braking
// reserve while preparation has not queued enough). Other units read the
// set point and some (C axis, synchronous operation, measuring) move axes
// of it.
#include <algorithm>
#include <optional>

#include "nck/core/rapid_override.hpp"
#include "nck/kernel/attachment.hpp"
#include "nck/kernel/command.hpp"
#include "nck/kernel/queues.hpp"
#include "nck/motion/path_profile.hpp"
#include "cycle.hpp"

namespace nck::kernel {

struct HscChain;  // hsc_chain.hpp

class PathUnit {
 public:
  // setup: which override scales G0 blocks (P-CHAN-00181).
  void set_rapid_override_mode(RapidOverrideMode m) noexcept { rapid_mode_ = m; }
  // Cycle start: whether the path moved in the cycle before. rt
  void begin_cycle() noexcept {
    moved_last_cycle_ = moved_this_cycle_;
    moved_this_cycle_ = false;
  }
  // A block starts: only motions (and blocks without motion in between)
  // continue a path at speed; anything else starts from standstill. A
  // motion's segment starts where the one before ended, or at `start`;
  // `map` maps it from program coordinates. rt
  void start_block(const Command& c, const StartPoint* start, const ProgramMap* map) noexcept;
  // Before its body: motion m starts where the set point stands now (after
  // a homing search moved the axes). rt
  void rejoin(const Motion& m) noexcept { segment_ = motion::Segment::joined(pos_, m.path); }
  // The body of motion m begins: its profile, ending no faster than the
  // queued commands leave room to brake in (braking_reserve.hpp). rt
  void start_motion(const Motion& m, const CommandQueue& queued, double dt_s) noexcept;
  // After start_motion: true when the block before ran into this one during
  // this cycle (the set point is the distance it ran past its end, s()). rt
  bool carry_on(const Motion& m) noexcept;
  // The last motion ended at speed: the next block takes over this cycle.
  bool passing() const noexcept { return passing_; }
  // The path moves, or ended its last motion at speed.
  bool moving() const noexcept { return velocity_ > 0 || passing_; }
  // One cycle of motion c (the couplings limited the profile before). rt
  motion::ProfileSample step(const Motion& m, const CommandQueue& queued, Cycle& cy) noexcept;
  // Motion c reached its end (its end point placed). rt
  void end_motion() noexcept;
  // The set point of motion m at path length s_mm: the segment's point,
  // mapped from program to machine coordinates when a rotation acts, and
  // from Cartesian to machine X/C under #FACE / #CYL. rt
  void place(const Motion& m, double s_mm, std::size_t n_axes) noexcept;
  // An operator hold at the end of the motion that runs: true once the path
  // can stop there within its deceleration (it then ends at standstill),
  // false while it is too fast for that. rt
  bool end_at_standstill(double dt_s) noexcept;
  // The path stands where it is (a G100 run ended at the probe). rt
  void halt() noexcept { velocity_ = 0; }
  // Program end: standstill, nothing carried on. rt
  void reset() noexcept;
  // E-stop: the path brakes along its path with at least a_mm_s2 until
  // the program ends (PathProfile::brake_for_emergency). rt
  void brake_for_emergency(double a_mm_s2) noexcept { profile_.brake_for_emergency(a_mm_s2); }

  const motion::AxisVector& position() const noexcept { return pos_; }
  motion::AxisVector& position() noexcept { return pos_; }
  double velocity_mm_s() const noexcept { return velocity_; }
  double s_mm() const noexcept { return profile_.s(); }
  // The segment of the motion that runs (or ran last).
  const motion::Segment& segment() const noexcept { return segment_; }
  // What the last step went to (time by cause; tick_io.hpp CycleCause).
  CycleCause cause() const noexcept { return cause_; }
  // The spindle-path couplings limit the profile each cycle.
  motion::PathProfile& profile() noexcept { return profile_; }

 private:
  void keep_braking_reserve(const Motion& m, const CommandQueue& queued, double dt_s) noexcept;
  void note_chain(const HscChain& h) noexcept;
  void note_starved(Cycle& cy) noexcept;
  // What limited step st (v_prev: the speed before it). rt
  CycleCause classify(const Motion& m, const motion::ProfileSample& st, double v_prev, double ovr,
                      const Cycle& cy) noexcept;

  // The override factor (0..1) of motion m in this cycle. rt
  double override_factor(const Motion& m, const Cycle& cy) const noexcept;

  RapidOverrideMode rapid_mode_ = RapidOverrideMode::not_used;
  motion::PathProfile profile_{};
  motion::Segment segment_{};
  std::optional<AffineMap> map_;  // the segment is in program coordinates
  motion::AxisVector pos_{};
  double velocity_ = 0;
  bool passing_ = false;  // the last motion ended at speed: the next one takes over this cycle
  bool reserve_ = false;  // the motion's end speed is lowered: its successors are not all queued yet
  bool starved_ = false;  // the braking reserve slowed the path (a KernelPrepStarved episode)
  bool moved_this_cycle_ = false, moved_last_cycle_ = false;  // the path advanced in this / the last cycle
  CycleCause cause_ = CycleCause::transition;
  CycleCause ramp_ = CycleCause::none;  // a speed-up under way: from standstill or out of a corner
  bool out_of_corner_stop_ = false;     // the last motion stopped for its corner (Motion::corner_stop)
  // HSC: the motion starts a chain; it reaches the end of the queue (looked
  // at again when the queue grows, from queue size hsc_seen_ on).
  bool hsc_chained_ = false, hsc_open_ = false;
  std::size_t hsc_seen_ = 0;
};

inline double PathUnit::override_factor(const Motion& m, const Cycle& cy) const noexcept {
  if (cy.in.feedhold || cy.stopped || cy.resetting) return 0.0;
  const bool rapid = !cy.block.feed_motion && !m.measure;  // G0 (a G100 run moves at F)
  if (!rapid) return std::clamp(cy.in.feed_override_pct, 0.0, 100.0) / 100.0;
  return rapid_override_factor(rapid_mode_, cy.in.feed_override_pct, cy.in.rapid_override_pct);
}

// Every cycle of a motion: defined here so that it inlines into the channel.
inline motion::ProfileSample PathUnit::step(const Motion& m, const CommandQueue& queued, Cycle& cy) noexcept {
  const double ovr = override_factor(m, cy);
  if (reserve_ || hsc_open_) keep_braking_reserve(m, queued, cy.dt_s);
  const double v_prev = profile_.v();
  const motion::ProfileSample st = profile_.step(cy.dt_s, ovr);
  if (reserve_ && st.braking) note_starved(cy);
  moved_this_cycle_ = st.v_mm_s > 0;
  velocity_ = st.v_mm_s;
  cause_ = classify(m, st, v_prev, ovr, cy);
  if (st.finished || st.v_mm_s > 0) out_of_corner_stop_ = st.finished && m.corner_stop;
  return st;
}

}  // namespace nck::kernel
