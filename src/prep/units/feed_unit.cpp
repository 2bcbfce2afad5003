// Feed and feed links in preparation; see feed_unit.hpp.
#include "nck/prep/units/feed_unit.hpp"

#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "nck/kernel/feed_link.hpp"

namespace nck::prep {
namespace {

constexpr PathSpeed kCoupled{PathSpeed::Kind::axes_max, 0};

bool tapping(nc::Motion m) {
  return m == nc::Motion::tap || m == nc::Motion::tap_rigid || m == nc::Motion::tap_retract;
}

}  // namespace

FeedUnit::FeedUnit(const config::ChannelConfig& channel, const std::vector<std::int8_t>& spindles)
    : main_(MainSpindle::find(channel, spindles)) {}

PlanResult FeedUnit::plan_block(const nc::Block& b, PlannedCommand& c, const PlanContext& ctx,
                                const PlannedSpindle& main) {
  const nc::ModalState& m = b.modal;
  const bool needs_spindle = m.feed_mode == nc::FeedMode::g95 || m.speed_mode == nc::SpeedMode::g96 ||
                             m.motion == nc::Motion::thread || tapping(m.motion);
  if (needs_spindle && !main_.exists())
    return block_error(ErrorId::KernelLinkNoSpindle, b, "G95/G96/G33/G63/G331 need a main spindle");
  if (tapping(m.motion)) {
    c.feed_link.kind = m.motion == nc::Motion::tap ? FeedLinkKind::tap : FeedLinkKind::tap_rigid;
    c.feed_link.spindle = main_.kernel;
  }
  if (m.motion == nc::Motion::tap_rigid && !tapping(prev_motion_)) {
    // G331 selected: the spindle goes to the thread start (0 deg) first.
    const double s_rpm = std::fabs(main.signed_speed_rpm);
    SpindleAction a;
    a.spindle = main_.kernel;
    a.op = SpindleOp::position;
    a.pos_deg = 0;
    a.rpm = s_rpm > 0 ? s_rpm : main_.vb_max_rpm(ctx.machine, ctx.channel, main.gear_stage) / 10;
    a.sync = SyncPoint::before;
    a.wait = SpindleWait::in_position;
    a.fn = TechKind::m;
    a.fn_number = 19;
    if (!c.attach_within(a, PlannedCommand::kMaxSpindleActions))
      return block_error(ErrorId::KernelSpindleTooManyActions, b, "too many spindle actions with G331");
  }
  prev_motion_ = m.motion;
  return {};
}

// G33: the pitch is given along one axis (I X, J Y, K Z); the path's mm per
// revolution scales it by length / that axis's travel.
PlanResult FeedUnit::thread_link(const nc::Block& b, const motion::AxisVector& start,
                                 const motion::AxisVector& target, double length_mm, FeedLink& f,
                                 const PlanContext& ctx) {
  for (int i = 0; i < 3; ++i)
    if (b.ijk[static_cast<std::size_t>(i)]) thread_axis_ = i;
  const int ax = ctx.axis_named(kMainAxisNames[thread_axis_]);
  const double travel =
      ax >= 0 ? std::fabs(target[static_cast<std::size_t>(ax)] - start[static_cast<std::size_t>(ax)]) : 0;
  if (ax < 0 || !(travel > 1e-9))
    return block_error(ErrorId::KernelThreadPitchAxisMissing, b,
                       fmt::format("G33 pitch {} belongs to {}, which {}", "IJK"[thread_axis_],
                                   kMainAxisNames[thread_axis_],
                                   ax < 0 ? "the channel does not have" : "does not move"));
  f.kind = FeedLinkKind::thread;
  f.mm_per_rev = b.modal.thread_pitch_mm * length_mm / travel;
  for (const nc::SpindleCommand& s : b.spindles)
    if (s.offset_deg && s.spindle_index && *s.spindle_index == main_.list_index) thread_offset_deg_ = *s.offset_deg;
  f.start_deg = thread_offset_deg_;
  // A thread chain must not slow down or stop between its blocks: the feed
  // override does not act on it (P-CHAN-00837, docs/decisions.md,
  // "Spindle-path couplings").
  f.ignore_override = ctx.channel.thread_ignore_override || ctx.channel.thread_chain;
  return {};
}

std::expected<PathSpeed, Diagnostic> FeedUnit::plan_feed(const nc::Block& b, const motion::AxisVector& start,
                                                      const motion::AxisVector& target, double length_mm,
                                                      PlannedCommand& c, const PlanContext& ctx,
                                                      const PlannedSpindle& main) {
  const nc::ModalState& m = b.modal;
  const double s_rpm = main.signed_speed_rpm;  // the main spindle's last S
  FeedLink& f = c.feed_link;
  f.spindle = main_.kernel;
  if (m.motion == nc::Motion::thread) {
    if (auto r = thread_link(b, start, target, length_mm, f, ctx); !r) return std::unexpected(r.error());
    return kCoupled;
  }
  if (m.motion == nc::Motion::tap) {
    // G63: F = S x pitch, so the pitch is F / S; the spindle follows the path.
    if (!(m.feed_mm_min > 0))
      return block_error(ErrorId::KernelNoFeed, b, "G63 with F0: program the tapping feed");
    if (s_rpm == 0) return block_error(ErrorId::NcTapSpeedZero, b, "G63 with S0: program the tapping speed");
    f.mm_per_rev = m.feed_mm_min / std::fabs(s_rpm);
    f.direction = s_rpm < 0 ? -1 : 1;
    f.spindle_max_rpm = main_.axis_vb_max_rpm(ctx.machine, ctx.channel);
    return PathSpeed{PathSpeed::Kind::programmed, m.feed_mm_min / 60.0};
  }
  if (m.motion == nc::Motion::tap_rigid || m.motion == nc::Motion::tap_retract) {
    if (s_rpm == 0) return block_error(ErrorId::NcTapSpeedZero, b, "G331/G332 need a spindle speed S");
    // The pitch's sign picks the thread hand; G332 turns the other way.
    f.mm_per_rev = std::fabs(m.tap_pitch_mm);
    f.direction = (m.tap_pitch_mm < 0 ? -1 : 1) * (m.motion == nc::Motion::tap_retract ? -1 : 1);
    return PathSpeed{PathSpeed::Kind::programmed, kernel::link_velocity_mm_s(s_rpm, f.mm_per_rev)};
  }
  if (m.feed_mode == nc::FeedMode::g95) {
    if (!(m.feed_mm_rev > 0)) return block_error(ErrorId::KernelNoFeed, b, "F is 0: program a feed in mm/rev (G95)");
    f.kind = FeedLinkKind::per_rev;
    f.mm_per_rev = m.feed_mm_rev;
    if (config::is_plc_spindle(ctx.machine, ctx.channel.spindles[main_.list_index])) {
      // A PLC spindle: programmed values only (TF5200 G95; docs/nc-language.md).
      const double rpm = main.speed_rpm.value_or(0);
      if (!(rpm > 0))
        return block_error(ErrorId::KernelFeedPerRevSpindleStopped, b, "G95 without a programmed spindle speed");
      f.use_programmed = true;
      f.programmed_rpm = rpm;
    }
    return kCoupled;
  }
  if (m.feed_mode == nc::FeedMode::g194) {
    // G194: F % of the path's maximum speed (the axes' max_speed_mm_s); set by the planner.
    if (!(m.feed_pct > 0))
      return block_error(ErrorId::KernelNoFeed, b, "F is 0: program a weighting in % (G194)");
    return PathSpeed{PathSpeed::Kind::share_of_max, m.feed_pct / 100.0};
  }
  if (m.feed_mode == nc::FeedMode::g93) {
    // G93: F is the block's time in seconds.
    if (!(m.feed_time_s > 0))
      return block_error(ErrorId::KernelNoFeed, b, "F is 0: program the block time in s (G93)");
    return PathSpeed{PathSpeed::Kind::programmed, length_mm / m.feed_time_s};
  }
  // G94: F in mm/min.
  if (!(m.feed_mm_min > 0)) return block_error(ErrorId::KernelNoFeed, b, "F is 0: program a feed in mm/min");
  return PathSpeed{PathSpeed::Kind::programmed, m.feed_mm_min / 60.0};
}

}  // namespace nck::prep
