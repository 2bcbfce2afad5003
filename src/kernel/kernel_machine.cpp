// The machine as E-stop and machine on leave it after a cycle: whether the
// drives may stay powered, and the `machine` event when anything changed.
#include "nck/kernel/kernel.hpp"

#include "channel.hpp"
#include "spindle_unit.hpp"

namespace nck::kernel {

// The drives are disabled once nothing moves any more under E-stop or
// machine off (the axes braked first), and enabled again as soon as
// neither holds. rt
void Kernel::follow_machine(const TickInput& in, double t_s, TickOutput& out) noexcept {
  bool amp_fault = false;  // an amplifier fault holds every drive off until its reset
  for (const auto& c : channels_) amp_fault = amp_fault || c->amp_fault_latched();
  const bool stop_drives = in.machine.estop || !in.machine.machine_on || amp_fault;
  bool moving = false;
  for (std::size_t i = 0; i < channels_.size(); ++i)
    moving = moving || out.channels[i].path_velocity_mm_s > 0 || channels_[i]->jogging();
  for (const SpindleUnit& u : spindles_) moving = moving || !u.axis.status().standstill;
  MachineOutput m;
  m.estop = in.machine.estop;
  m.machine_on = in.machine.machine_on;
  for (const auto& c : channels_) m.reset_needed = m.reset_needed || c->estop_latched() || c->amp_fault_latched();
  m.drives_enabled = !stop_drives || (machine_out_.drives_enabled && moving);
  if (m != machine_out_)
    out.emit(Event{{t_s, 0, {}}, m});
  machine_out_ = m;
  out.machine = m;
}

bool Kernel::estop_latched(std::size_t ch) const noexcept {
  return ch < channels_.size() && channels_[ch]->estop_latched();
}

bool Kernel::amp_fault_latched(std::size_t ch) const noexcept {
  return ch < channels_.size() && channels_[ch]->amp_fault_latched();
}

}  // namespace nck::kernel
