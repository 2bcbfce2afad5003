#include "nck/run/live_snapshot.hpp"

#include "nck/sim/dry_run.hpp"

namespace nck::app {

void fill_snapshot(const sim::DryRun& run, const kernel::TickOutput& out, LiveSnapshot& s) noexcept {
  fill_kernel_snapshot(run.kernel(), out, s);
  const plc::HliImage& hli = run.machine().hli();
  for (std::size_t ch = 0; ch < s.channel_count && ch < config::kMaxChannels; ++ch) s.channels[ch].hli = hli.channel[ch];
  for (std::size_t i = 0; i < s.spindle_count && i < s.spindle_override_pct.size(); ++i)
    s.spindle_override_pct[i] = hli.spindle_control[i].effective_override_percent();
}

}  // namespace nck::app
