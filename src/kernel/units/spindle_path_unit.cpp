#include "spindle_path_unit.hpp"

#include <cmath>

namespace nck::kernel {
namespace {

bool is_tap(FeedLinkKind k) noexcept { return k == FeedLinkKind::tap || k == FeedLinkKind::tap_rigid; }

// The gear stage's top speed (max_speed_mm_s) in rpm, 0 = none.
double vb_max_rpm(const SpindleUnit& u) noexcept {
  const std::uint32_t g = u.axis.status().gear_stage;
  if (g < 1 || g > u.axis.config().gears.size()) return 0;
  return u.axis.config().gears[g - 1].speed_max_deg_s / 6.0;
}

}  // namespace

// A block outside G63/G331/G332 ends the tracking (G4 and blocks without
// motion under G63 keep it, FCT-S1 2.8.6); G96 is taken over from every
// block (G97 freezes the speed reached).
void SpindlePathUnit::start(const FeedLink* f, const CssLink* css, ChannelContext& ctx) noexcept {
  link_ = f ? *f : FeedLink{};
  if (!is_tap(link_.kind)) release_tap_spindle(ctx);
  const CssLink next = css ? *css : CssLink{};
  if (SpindleUnit* u = ctx.spindle(css_.spindle); u && !(next.active && next.spindle == css_.spindle))
    u->speed_law = false;
  css_ = next;
}

void SpindlePathUnit::end(ChannelContext& ctx) noexcept {
  release_tap_spindle(ctx);
  start(nullptr, nullptr, ctx);
}

void SpindlePathUnit::release_tap_spindle(ChannelContext& ctx) noexcept {
  if (SpindleUnit* u = ctx.spindle(tap_spindle_)) (void)u->axis.leave_axis_mode();
  tap_spindle_ = -1;
}

// Tapping makes the spindle a tracking axis (it must stand still, 950008),
// G95/G33 need a turning spindle (60131), G33 waits for the spindle's start
// angle.
// The spindle angle G33 starts on: the measured one where the machine
// measures the spindle (an encoder's angle: every pass meets the groove the
// spindle cut, whatever its drive's speed error or lag), else the set point
// (the dry run: docs/decisions.md, "G33 on the measured angle"). rt
double SpindlePathUnit::thread_angle_deg(const SpindleUnit& u) noexcept {
  const spindle::SpindleStatus& st = u.axis.status();
  return u.machine_measured ? st.act_pos_deg : st.set_pos_deg;
}

Fault SpindlePathUnit::start_motion(motion::PathProfile& path, ChannelContext& ctx) noexcept {
  const FeedLink& f = link_;
  thread_waiting_ = false;
  SpindleUnit* u = ctx.spindle(f.spindle);
  if (f.kind == FeedLinkKind::none || !u) return {};
  const spindle::SpindleStatus& st = u->axis.status();
  if (is_tap(f.kind)) {
    if (tap_spindle_ != f.spindle) {
      const spindle::SpindleResult r = u->axis.enter_axis_mode();
      if (!r.ok()) return {r.id};
      tap_spindle_ = f.spindle;
    }
    tap_start_deg_ = u->axis.status().set_pos_deg;
    return {};
  }
  const bool turning = st.mode == spindle::SpindleMode::rotate && st.cmd_rpm != 0;
  if (!f.use_programmed && !turning) return {ErrorId::KernelFeedPerRevSpindleStopped};
  if (f.kind == FeedLinkKind::thread) {
    thread_waiting_ = !f.chained;  // a chained block goes on in the groove of the first
    thread_last_deg_ = thread_angle_deg(*u);
  }
  path.set_override_ignored(f.kind == FeedLinkKind::thread && f.ignore_override);
  return {};
}

void SpindlePathUnit::limit_path(motion::PathProfile& path, ChannelContext& ctx) noexcept {
  const FeedLink& f = link_;
  const SpindleUnit* u = ctx.spindle(f.spindle);
  if (f.kind == FeedLinkKind::none || !u) return;
  const spindle::SpindleStatus& st = u->axis.status();
  switch (f.kind) {
    case FeedLinkKind::per_rev:
      // The spindle's set-point speed of this cycle (docs/decisions.md, "Spindle-path couplings": a
      // ramping spindle takes the feed with it).
      path.set_velocity_limit(link_velocity_mm_s(f.use_programmed ? f.programmed_rpm : st.set_rpm, f.mm_per_rev));
      break;
    case FeedLinkKind::thread: {
      if (thread_waiting_) {
        // Start on the zero mark + OFFSET, so every pass meets the same
        // groove; while the encoder's index reset is pending its angle is
        // no reference yet (its reset is the zero mark passing).
        const double angle_deg = thread_angle_deg(*u);
        const double step = angle_deg - thread_last_deg_;
        const double fwd = st.set_rpm >= 0 ? std::fmod(step + 720.0, 360.0) : -std::fmod(-step + 720.0, 360.0);
        const bool index_pending = u->machine_measured && u->axis.feedback().index_reset_pending;
        thread_waiting_ = index_pending || !passes_angle(thread_last_deg_, fwd, f.start_deg);
        thread_last_deg_ = angle_deg;
      }
      path.set_velocity_limit(thread_waiting_ ? 0.0 : link_velocity_mm_s(st.act_rpm, f.mm_per_rev));
      break;
    }
    case FeedLinkKind::tap:
    case FeedLinkKind::tap_rigid:
      // The spindle follows; its top speed caps the path.
      path.set_velocity_limit(
          link_velocity_mm_s(f.spindle_max_rpm > 0 ? f.spindle_max_rpm : vb_max_rpm(*u), f.mm_per_rev));
      break;
    case FeedLinkKind::none: break;
  }
}

void SpindlePathUnit::announce_wait(Cycle& cy) noexcept {
  if (thread_waiting_ == wait_announced_) return;
  wait_announced_ = thread_waiting_;
  const ev::Wait e{WaitReason::zero_mark, ev::spindle_or_none(link_.spindle)};
  if (thread_waiting_) cy.emit(e);
  else cy.emit(ev::WaitEnd{e});
}

// Time by cause's ideal (ChannelOutput::feed_mm_s): the programmed speed,
// not the set point, so a spindle still ramping up, its override or a limit
// show as time lost, as a G94 feed the axes cannot reach does.
double SpindlePathUnit::commanded_feed_mm_s(double planned_mm_s, const ChannelContext& ctx) const noexcept {
  const FeedLink& f = link_;
  if (f.kind != FeedLinkKind::per_rev && f.kind != FeedLinkKind::thread) return planned_mm_s;
  if (f.use_programmed) return link_velocity_mm_s(f.programmed_rpm, f.mm_per_rev);
  const SpindleUnit* u = ctx.spindle(f.spindle);
  return u ? link_velocity_mm_s(u->axis.status().programmed_rpm, f.mm_per_rev) : planned_mm_s;
}

void SpindlePathUnit::follow_path(double s_mm, double v_mm_s, ChannelContext& ctx) noexcept {
  const FeedLink& f = link_;
  if (!is_tap(f.kind) || tap_spindle_ != f.spindle) return;
  SpindleUnit* u = ctx.spindle(f.spindle);
  if (!u) return;
  const double pos = tap_angle_deg(tap_start_deg_, s_mm, f.mm_per_rev, f.direction);
  const double vel = (f.direction < 0 ? -360.0 : 360.0) * v_mm_s / f.mm_per_rev;
  u->axis.axis_set_point(pos, vel);
}

// n = 1000 v / (2 pi r) from the face axis's set point, for a spindle in
// endless rotation (its direction kept).
void SpindlePathUnit::follow_css(const motion::AxisVector& pos_mm, const motion::AxisVector& manual_mm,
                                 ChannelContext& ctx) noexcept {
  SpindleUnit* u = ctx.spindle(css_.spindle);
  if (!css_.active || !u || css_.face_axis < 0) return;
  const spindle::SpindleStatus& st = u->axis.status();
  if (st.mode != spindle::SpindleMode::rotate) return;
  const auto j = static_cast<std::size_t>(css_.face_axis);
  const double r_mm = pos_mm[j] + manual_mm[j] - css_.centre_mm;  // the machine set point
  const double n = css_speed_rpm(css_.v_m_min, r_mm, css_.max_rpm, vb_max_rpm(*u));
  const double dir = u->rotation_dir < 0 ? -1.0 : 1.0;
  u->speed_law = true;
  if (dir * n != st.programmed_rpm) (void)u->axis.rotate(dir * n);
}

}  // namespace nck::kernel
