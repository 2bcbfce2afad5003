// The kernel's drives (DriveUnits: CiA 402 and conventional) and what
// they exchange with its path axes and spindles each cycle.
#include <cmath>

#include "drive_units.hpp"
#include "nck/kernel/kernel.hpp"
#include "spindle_unit.hpp"

namespace nck::kernel {

namespace cia = drives::cia402;

namespace {

// The drive mode a spindle's state asks for (FCT-S1's state graph for
// digital drives): positioning, a gear change's approach and the C axis
// are position-controlled; a speed-controlled spindle turns and stops in
// velocity mode. Homing mode is DriveUnits' (while the drive homes).
cia::Mode spindle_drive_mode(const spindle::SpindleAxis& a) noexcept {
  switch (a.status().mode) {
    case spindle::SpindleMode::position:
    case spindle::SpindleMode::gear_change:
    case spindle::SpindleMode::axis: return cia::Mode::cyclic_sync_position;
    default:
      return a.config().open_loop ? cia::Mode::cyclic_sync_velocity : cia::Mode::cyclic_sync_position;
  }
}

}  // namespace

// The drives' set points: each channel path axis's set point in its drive's
// coordinates (the machine set point plus homing's drive offset) with its
// velocity from the last one (mm, mm/s) and whether G74 lets its CiA 402
// drive home; each CiA 402 spindle's mode
// and increments; each conventional spindle's velocity. rt
void Kernel::write_drive_set_points(const TickInput& in, TickOutput& out) noexcept {
  for (std::size_t c = 0; c < machine_->channels.size(); ++c) {
    const config::ChannelConfig& ch = machine_->channels[c];
    for (std::size_t j = 0; j < ch.axes.size() && j < kMaxAxes; ++j) {
      const int a = ch.axes[j].axis_index;
      if (a < 0 || static_cast<std::size_t>(a) >= drives::kMaxDrives) continue;
      const ChannelOutput& o = out.channels[c];
      drive_units_->write_set_point(static_cast<std::size_t>(a), o.drive_pos(j), (o.drive_homing_axes >> j & 1u) != 0,
                                    in, out);
    }
  }
  for (const SpindleUnit& u : spindles_) {
    if (u.conventional_axis >= 0) {
      // The position loop is the NC's while the spindle is position-controlled
      // (FCT-S1's modes: M19, gear change approach, C axis, a closed-loop
      // spindle), with the kv of the gear stage in force; else the drive
      // controls the speed itself.
      const auto a = static_cast<std::size_t>(u.conventional_axis);
      const spindle::DriveCommand c = u.axis.drive_command();
      double vel_deg_s = c.step_deg / cycle_s_;
      if (spindle_drive_mode(u.axis) == cia::Mode::cyclic_sync_position)
        vel_deg_s += machine_->axes[a].gear(c.gear_stage).position_gain_1_s * u.axis.drive_following_error_deg();
      drive_units_->write_spindle_velocity(a, c.pos_deg, vel_deg_s, out);
      continue;
    }
    if (u.cia402_axis < 0) continue;
    const DriveUnits::SpindleCycle cycle{spindle_drive_mode(u.axis), u.axis.drive_command().step_deg,
                                         u.axis.awaits_drive_homing()};
    drive_units_->write_spindle(static_cast<std::size_t>(u.cia402_axis), cycle, in, out);
  }
}

// A drive that homed in this cycle's step: its position is its spindle's. rt
void Kernel::take_drive_homing(const TickInput& in) noexcept {
  for (SpindleUnit& u : spindles_) {
    const auto a = static_cast<std::size_t>(u.cia402_axis);
    if (u.cia402_axis >= 0 && drive_units_->homing_attained(a)) u.axis.drive_homed(in.drives[a].actual_pos);
  }
}

// A spindle's CiA 402 drive measures its speed and position (true), taken
// as the spindle's feedback while the drive is in operation. The position
// is the set point less the drive's following error, so that the drive's
// own position scale (not homed yet, or never wrapped) does not matter. rt
bool Kernel::take_spindle_drive(SpindleUnit& u, const TickInput& in) noexcept {
  if (u.cia402_axis < 0 || !drive_units_) return false;
  const auto a = static_cast<std::size_t>(u.cia402_axis);
  const drives::DriveFeedback& fb = in.drives[a];
  const bool valid = cia::decode(fb.statusword) == cia::State::operation_enabled;
  const spindle::DriveFeedback m{fb.actual_vel, u.axis.drive_command().pos_deg - drive_units_->lag(a, in), valid};
  if (m.valid || u.axis.feedback().valid) u.axis.take_feedback(m);
  return true;
}

}  // namespace nck::kernel
