#include "nck/sim/cia402_drives.hpp"

namespace nck::sim {

namespace cia = drives::cia402;

Cia402Drives::Cia402Drives(const config::Machine& m) {
  for (auto& ch : axis_of_) ch.fill(-1);
  for (std::size_t i = 0; i < m.axes.size() && i < drives::kMaxDrives; ++i)
    if (m.axes[i].is_cia402()) present_[present_count_++] = static_cast<std::uint8_t>(i);
  for (std::size_t c = 0; c < m.channels.size() && c < config::kMaxChannels; ++c)
    for (std::size_t j = 0; j < m.channels[c].axes.size() && j < kMaxAxes; ++j)
      axis_of_[c][j] = static_cast<std::int16_t>(m.channels[c].axes[j].axis_index);
}

void Cia402Drives::read(kernel::TickInput& in) const noexcept {
  for (std::size_t k = 0; k < present_count_; ++k) in.drives[present_[k]] = drives_[present_[k]].fb;
}

void Cia402Drives::write(const kernel::TickOutput& out) noexcept {
  for (std::size_t k = 0; k < present_count_; ++k) {
    const std::size_t i = present_[k];
    Drive& d = drives_[i];
    const drives::DriveCommand& cmd = out.drives[i];
    const std::uint16_t bits = d.device.step(cmd.controlword, d.fault);
    const bool enabled = d.device.state() == cia::State::operation_enabled;
    d.fb.statusword = static_cast<std::uint16_t>(bits | (enabled ? cia::sw::target_reached : 0));
    d.fb.mode_display = enabled ? cmd.mode_of_operation : std::int8_t{0};
    d.fb.fault = d.device.state() == cia::State::fault;
    // An ideal drive: while enabled it stands where the NC commands it; else it holds.
    if (enabled) {
      d.fb.actual_vel = cmd.target_vel;
      d.fb.actual_pos = cmd.target_pos;
    } else {
      d.fb.actual_vel = 0;
    }
    d.fb.following_error = enabled ? 0.0 : cmd.target_pos - d.fb.actual_pos;
  }
}

void Cia402Drives::set_fault(std::size_t ch, std::size_t j, bool on) noexcept {
  if (ch >= config::kMaxChannels || j >= kMaxAxes) return;
  const std::int16_t a = axis_of_[ch][j];
  if (a < 0 || static_cast<std::size_t>(a) >= drives::kMaxDrives) return;
  drives_[static_cast<std::size_t>(a)].fault = on;
}

}  // namespace nck::sim
