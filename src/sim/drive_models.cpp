#include "nck/sim/drive_models.hpp"

namespace nck::sim {

DriveModels::DriveModels(const config::Machine& m) : cycle_s_(m.cycle_time_us * 1e-6) {
  for (auto& ch : axis_of_) ch.fill(-1);
  for (std::size_t i = 0; i < m.axes.size() && i < drives::kMaxDrives; ++i) {
    if (!m.axes[i].is_cia402() && !m.axes[i].is_conventional()) continue;
    present_[present_count_++] = static_cast<std::uint8_t>(i);
    drives_[i].conventional = m.axes[i].is_conventional();
  }
  for (std::size_t c = 0; c < m.channels.size() && c < config::kMaxChannels; ++c)
    for (std::size_t j = 0; j < m.channels[c].axes.size() && j < kMaxAxes; ++j)
      axis_of_[c][j] = static_cast<std::int16_t>(m.channels[c].axes[j].axis_index);
}

void DriveModels::read(kernel::TickInput& in) const noexcept {
  for (std::size_t k = 0; k < present_count_; ++k) in.drives[present_[k]] = drives_[present_[k]].drive.feedback();
}

void DriveModels::write(const kernel::TickOutput& out) noexcept {
  for (std::size_t k = 0; k < present_count_; ++k) {
    Drive& d = drives_[present_[k]];
    const drives::DriveCommand& cmd = out.drives[present_[k]];
    if (d.conventional) (void)d.drive.follow_velocity(cmd, cycle_s_);
    else (void)d.drive.step(cmd, d.fault, cycle_s_);
  }
}

void DriveModels::set_fault(std::size_t ch, std::size_t j, bool on) noexcept {
  if (ch >= config::kMaxChannels || j >= kMaxAxes) return;
  const std::int16_t a = axis_of_[ch][j];
  if (a < 0 || static_cast<std::size_t>(a) >= drives::kMaxDrives) return;
  drives_[static_cast<std::size_t>(a)].fault = on;
}

}  // namespace nck::sim
