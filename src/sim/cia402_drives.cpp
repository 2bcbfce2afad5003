#include "nck/sim/cia402_drives.hpp"

namespace nck::sim {

Cia402Drives::Cia402Drives(const config::Machine& m) {
  for (auto& ch : axis_of_) ch.fill(-1);
  for (std::size_t i = 0; i < m.axes.size() && i < drives::kMaxDrives; ++i)
    if (m.axes[i].is_cia402()) present_[present_count_++] = static_cast<std::uint8_t>(i);
  for (std::size_t c = 0; c < m.channels.size() && c < config::kMaxChannels; ++c)
    for (std::size_t j = 0; j < m.channels[c].axes.size() && j < kMaxAxes; ++j)
      axis_of_[c][j] = static_cast<std::int16_t>(m.channels[c].axes[j].axis_index);
}

void Cia402Drives::read(kernel::TickInput& in) const noexcept {
  for (std::size_t k = 0; k < present_count_; ++k) in.drives[present_[k]] = drives_[present_[k]].drive.feedback();
}

void Cia402Drives::write(const kernel::TickOutput& out) noexcept {
  for (std::size_t k = 0; k < present_count_; ++k) {
    Drive& d = drives_[present_[k]];
    (void)d.drive.step(out.drives[present_[k]], d.fault);
  }
}

void Cia402Drives::set_fault(std::size_t ch, std::size_t j, bool on) noexcept {
  if (ch >= config::kMaxChannels || j >= kMaxAxes) return;
  const std::int16_t a = axis_of_[ch][j];
  if (a < 0 || static_cast<std::size_t>(a) >= drives::kMaxDrives) return;
  drives_[static_cast<std::size_t>(a)].fault = on;
}

}  // namespace nck::sim
