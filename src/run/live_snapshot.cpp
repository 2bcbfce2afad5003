#include "nck/run/live_snapshot.hpp"

namespace nck::app {

void fill_snapshot(const sim::DryRun& run, const kernel::TickOutput& out, LiveSnapshot& s) noexcept {
  const kernel::Kernel& k = run.kernel();
  s.cycle = k.cycles();
  s.t_s = k.time_s();
  s.channel_count = k.channel_count();
  s.spindle_count = k.spindle_count();
  s.machine = out.machine;
  for (std::size_t ch = 0; ch < s.channel_count && ch < config::kMaxChannels; ++ch) {
    const kernel::ChannelOutput& o = out.channels[ch];
    LiveChannel& c = s.channels[ch];
    c.axis_mcs = o.axis_mcs;
    c.path_velocity_mm_s = o.path_velocity_mm_s;
    c.feed_mm_s = o.feed_mm_s;
    c.distance_to_go_mm = o.distance_to_go_mm;
    c.axis_dtg = o.axis_dtg;
    c.program_state = k.program_state(ch);
    c.cause = o.cause;
    c.wait_reason = o.wait_reason;
    c.homed_axes = o.homed_axes;
    c.homing_required = o.homing_required;
    c.at = k.channel_state(ch).at;
    c.hli = run.machine().hli().channel[ch];
  }
  s.spindles = out.spindles;
  s.hli_spindles = out.hli_spindles;
  for (std::size_t i = 0; i < s.spindle_count && i < s.spindle_override_pct.size(); ++i)
    s.spindle_override_pct[i] = run.machine().hli().spindle_control[i].effective_override_percent();
}

}  // namespace nck::app
