// Planning of the spindle-path couplings (FCT-S1 2.8.6, 2.8.7, 2.8.9; facts
// B7-B11): G93/G94/G95 feed, G33 thread cutting, G63 and G331/G332 tapping,
// G96 constant cutting speed. Preparation only describes the coupling
// (kernel::FeedLink, kernel::CssLink); the channel evaluates it each cycle.
#include <bit>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "nck/prep/planner.hpp"

namespace nck::prep {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool tapping(nc::Motion m) {
  return m == nc::Motion::tap || m == nc::Motion::tap_rigid || m == nc::Motion::tap_retract;
}

}  // namespace

// The main spindle: the channel spindle with log_achs_nr = main_spindle_ax_nr,
// else the first one.
void Planner::find_main_spindle(const std::vector<std::int8_t>& spindles) {
  for (std::size_t i = 0; i < channel_.spindles.size() && i < spindles.size(); ++i) {
    if (main_spindle_ < 0 || channel_.spindles[i].log_axis_nr == channel_.main_spindle_ax_nr) {
      main_spindle_ = spindles[i];
      main_channel_spindle_ = i;
    }
    if (channel_.spindles[i].log_axis_nr == channel_.main_spindle_ax_nr) break;
  }
}

// The main spindle's last programmed S, signed (G63 takes a negative S as
// the reverse direction).
void Planner::note_spindle_words(const nc::Block& b) {
  for (const nc::SpindleCommand& s : b.spindles)
    if (s.rev_rpm && s.spindle_index && *s.spindle_index == main_channel_spindle_) last_s_rpm_ = *s.rev_rpm;
}

// The speed limit of the main spindle's gear stage as planned, in rpm (0 = none).
double Planner::main_vb_max_rpm() const {
  if (main_channel_spindle_ >= channel_.spindles.size()) return 0;
  const int ax = channel_.spindles[main_channel_spindle_].axis_index;
  if (ax < 0 || !machine_ || static_cast<std::size_t>(ax) >= machine_->axes.size()) return 0;
  const std::uint32_t stage = spindles_.planned(main_channel_spindle_).gear_stage;
  return machine_->axes[static_cast<std::size_t>(ax)].gear(stage).vb_max / 6.0;  // deg/s -> rpm
}

// G63 makes the main spindle an axis in the gear stage of P-AXIS-00052
// (kenngr.def_cax_gear_st, FCT-S1 2.8.6), as #CAX does: its top speed in
// rpm (0 = none).
double Planner::main_cax_vb_max_rpm() const {
  if (main_channel_spindle_ >= channel_.spindles.size()) return 0;
  const int ax = channel_.spindles[main_channel_spindle_].axis_index;
  if (ax < 0 || !machine_ || static_cast<std::size_t>(ax) >= machine_->axes.size()) return 0;
  const config::AxisConfig& a = machine_->axes[static_cast<std::size_t>(ax)];
  return a.gear(a.def_cax_gear_st).vb_max / 6.0;  // deg/s -> rpm
}

// What every command of a block carries: G96 (modal), the tapping mark (the
// spindle stays a tracking axis while G63/G331/G332 is modal, G4 included),
// and the positioning of the spindle when G331 is selected. Errors as a command.
std::optional<Command> Planner::plan_links(const nc::Block& b, Command& c) {
  const nc::ModalState& m = b.modal;
  const bool needs_spindle = m.feed_mode == nc::FeedMode::g95 || m.speed_mode == nc::SpeedMode::g96 ||
                             m.motion == nc::Motion::thread || tapping(m.motion);
  if (needs_spindle && main_spindle_ < 0)
    return error_command(ErrorId::KernelLinkNoSpindle, "G95/G96/G33/G63/G331 need a main spindle",
                         b.file_id, b.line);
  if (tapping(m.motion)) {
    c.feed_link.kind = m.motion == nc::Motion::tap ? FeedLinkKind::tap : FeedLinkKind::tap_rigid;
    c.feed_link.spindle = main_spindle_;
  }
  if (m.motion == nc::Motion::tap_rigid && !tapping(prev_motion_)) {
    // G331 selected: the spindle goes to the thread start (0 deg) first.
    SpindleAction a;
    a.spindle = main_spindle_;
    a.op = SpindleOp::position;
    a.pos_deg = 0;
    a.rpm = std::fabs(last_s_rpm_) > 0 ? std::fabs(last_s_rpm_) : main_vb_max_rpm() / 10;
    a.sync = SyncPoint::before;
    a.wait = SpindleWait::in_position;
    a.fn = 'M';
    a.fn_number = 19;
    if (!c.spindle_actions.push_back(a))
      return error_command(ErrorId::KernelSpindleTooManyActions, "too many spindle actions with G331",
                           b.file_id, b.line);
  }
  prev_motion_ = m.motion;
  if (m.speed_mode != nc::SpeedMode::g96 || !(m.css_m_min > 0)) return std::nullopt;
  // The face-turning axis (kenngr.achs_mode 0x40), else the axis named X.
  const int x = face_axes_ != 0 ? std::countr_zero(face_axes_) : axis_named("X");
  if (x < 0)
    return error_command(ErrorId::KernelCssNoFaceAxis, "G96 needs a face axis (achs_mode 0x40, or one named X)",
                         b.file_id, b.line);
  const bool new_speed = !css_on_ || css_m_min_ != m.css_m_min;
  // The radius is the tool tip's: the programmed X plus the zero offsets, i.e.
  // the machine X less the tool offset (docs/decisions.md). Where the
  // turning centre is in machine X: 0 shifted by the tool offset.
  const auto ux = static_cast<std::size_t>(x);
  const double tool_mm = frames_.to_mcs(pcs_, frames::SuppressMask::none())[ux] -
                         frames_.to_mcs(pcs_, frames::SuppressMask{frames::SuppressMask::kTool})[ux];
  c.css = {true, main_spindle_, static_cast<std::int8_t>(x), m.css_m_min, m.max_speed_rpm, tool_mm};
  css_on_ = true;
  css_m_min_ = m.css_m_min;
  // The start speed comes from where the face axis was last programmed (facts B11).
  const double r_mm = mcs_[ux] - tool_mm;
  if (new_speed && kernel::css_limited(m.css_m_min, r_mm, m.max_speed_rpm, main_vb_max_rpm()))
    (void)c.warnings.push_back(
        {ErrorId::KernelCssStartLimited,
         store_.add_message(fmt::format("G96 S{}: at radius {:.3f} mm the start speed is limited to {:.1f} rpm",
                                        m.css_m_min, r_mm,
                                        kernel::css_speed_rpm(m.css_m_min, r_mm, m.max_speed_rpm,
                                                              main_vb_max_rpm())))});
  return std::nullopt;
}

// G33: the pitch is given along one axis (I X, J Y, K Z); the path's mm per
// revolution scales it by length / that axis's travel.
std::optional<Command> Planner::thread_link(const nc::Block& b, const motion::AxisVector& start,
                                            const motion::AxisVector& target, double length_mm,
                                            FeedLink& f) {
  for (int i = 0; i < 3; ++i)
    if (b.ijk[static_cast<std::size_t>(i)]) thread_axis_ = i;
  const int ax = axis_named(kMainAxisNames[thread_axis_]);
  const double travel = ax >= 0 ? std::fabs(target[static_cast<std::size_t>(ax)] - start[static_cast<std::size_t>(ax)]) : 0;
  if (ax < 0 || !(travel > 1e-9))
    return error_command(ErrorId::KernelThreadPitchAxisMissing,
                         fmt::format("G33 pitch {} belongs to {}, which {}", "IJK"[thread_axis_],
                                     kMainAxisNames[thread_axis_], ax < 0 ? "the channel does not have" : "does not move"),
                         b.file_id, b.line);
  f.kind = FeedLinkKind::thread;
  f.mm_per_rev = b.modal.thread_pitch_mm * length_mm / travel;
  for (const nc::SpindleCommand& s : b.spindles)
    if (s.offset_deg && s.spindle_index && *s.spindle_index == main_channel_spindle_) thread_offset_deg_ = *s.offset_deg;
  f.start_deg = thread_offset_deg_;
  // A thread chain must not slow down or stop between its blocks: the feed
  // override does not act on it (P-CHAN-00837, docs/decisions.md).
  f.ignore_override = channel_.thread_ignore_override || channel_.thread_chain;
  return std::nullopt;
}

// The commanded path speed of a feed block (G1/G2/G3/G33/G63/G331/G332),
// +infinity when a coupling sets it each cycle (the coupling in c.feed_link),
// negative for G194: minus the share of the path's maximum speed.
std::optional<Command> Planner::plan_feed(const nc::Block& b, const motion::AxisVector& start,
                                          const motion::AxisVector& target, double length_mm, Command& c,
                                          double& v_cmd) {
  const nc::ModalState& m = b.modal;
  FeedLink& f = c.feed_link;
  f.spindle = main_spindle_;
  if (m.motion == nc::Motion::thread) {
    v_cmd = kInf;
    return thread_link(b, start, target, length_mm, f);
  }
  if (m.motion == nc::Motion::tap) {
    // G63: F = S x pitch, so the pitch is F / S; the spindle follows the path.
    if (!(m.feed_mm_min > 0))
      return error_command(ErrorId::KernelNoFeed, "G63 with F0: program the tapping feed", b.file_id, b.line);
    if (last_s_rpm_ == 0)
      return error_command(ErrorId::NcTapSpeedZero, "G63 with S0: program the tapping speed", b.file_id, b.line);
    f.mm_per_rev = m.feed_mm_min / std::fabs(last_s_rpm_);
    f.direction = last_s_rpm_ < 0 ? -1 : 1;
    f.spindle_max_rpm = main_cax_vb_max_rpm();
    v_cmd = m.feed_mm_min / 60.0;
    return std::nullopt;
  }
  if (m.motion == nc::Motion::tap_rigid || m.motion == nc::Motion::tap_retract) {
    if (last_s_rpm_ == 0)
      return error_command(ErrorId::NcTapSpeedZero, "G331/G332 need a spindle speed S", b.file_id, b.line);
    // The pitch's sign picks the thread hand; G332 turns the other way.
    f.mm_per_rev = std::fabs(m.tap_pitch_mm);
    f.direction = (m.tap_pitch_mm < 0 ? -1 : 1) * (m.motion == nc::Motion::tap_retract ? -1 : 1);
    v_cmd = kernel::link_velocity_mm_s(last_s_rpm_, f.mm_per_rev);
    return std::nullopt;
  }
  if (m.feed_mode == nc::FeedMode::g95) {
    if (!(m.feed_mm_rev > 0))
      return error_command(ErrorId::KernelNoFeed, "F is 0: program a feed in mm/rev (G95)", b.file_id, b.line);
    f.kind = FeedLinkKind::per_rev;
    f.mm_per_rev = m.feed_mm_rev;
    if (config::is_plc_spindle(*machine_, channel_.spindles[main_channel_spindle_])) {
      // A PLC spindle: programmed values only (facts B10).
      const double rpm = spindles_.planned(main_channel_spindle_).speed_rpm.value_or(0);
      if (!(rpm > 0))
        return error_command(ErrorId::KernelFeedPerRevSpindleStopped, "G95 without a programmed spindle speed",
                             b.file_id, b.line);
      f.use_programmed = true;
      f.programmed_rpm = rpm;
    }
    v_cmd = kInf;
    return std::nullopt;
  }
  if (m.feed_mode == nc::FeedMode::g194) {
    // G194: F % of the path's maximum speed (the axes' vb_max); set by plan_motion.
    if (!(m.feed_pct > 0))
      return error_command(ErrorId::KernelNoFeed, "F is 0: program a weighting in % (G194)", b.file_id, b.line);
    v_cmd = -m.feed_pct / 100.0;  // a share of v_max, negative as a mark
    return std::nullopt;
  }
  if (m.feed_mode == nc::FeedMode::g93) {
    // G93: F is the block's time in seconds.
    if (!(m.feed_time_s > 0))
      return error_command(ErrorId::KernelNoFeed, "F is 0: program the block time in s (G93)", b.file_id, b.line);
    v_cmd = length_mm / m.feed_time_s;
    return std::nullopt;
  }
  if (!(m.feed_mm_min > 0))
    return error_command(ErrorId::KernelNoFeed, "F is 0: program a feed in mm/min", b.file_id, b.line);
  v_cmd = m.feed_mm_min / 60.0;
  return std::nullopt;
}

}  // namespace nck::prep
