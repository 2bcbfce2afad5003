#pragma once
// What the live kernel publishes after every cycle (nck serve): plain data,
// copied into a triple buffer by the kernel thread and read by the server
// thread, which turns it into the stream's JSON (docs/api.md). The Python
// session fills one from its run for the same state document
// (run/state_document.hpp).
#include <array>
#include <cstdint>
#include <type_traits>

#include "nck/config/machine.hpp"
#include "nck/kernel/event.hpp"
#include "nck/kernel/tick_io.hpp"
#include "nck/kernel/kernel.hpp"
#include "nck/plc/hli.hpp"

namespace nck::sim {
class DryRun;
}

namespace nck::app {

// A channel that runs no program (idle, ended, failed): a program may be
// loaded or started, and its cycles go to no cause.
inline bool channel_free(kernel::ProgramState st) {
  return st == kernel::ProgramState::idle || st == kernel::ProgramState::ended || st == kernel::ProgramState::error;
}

struct LiveChannel {
  AxisArray axis_mcs{};
  double path_velocity_mm_s = 0;
  double feed_mm_s = 0;  // the motion's programmed velocity
  double distance_to_go_mm = 0;
  AxisArray axis_dtg{};  // per axis: the motion's end minus the set point
  kernel::ProgramState program_state = kernel::ProgramState::idle;
  kernel::CycleCause cause = kernel::CycleCause::none;
  kernel::WaitReason wait_reason = kernel::WaitReason::plc_ack;
  BlockRef at{};  // the block the channel stands at
  plc::ChannelControl hli{};  // the operator's controls as the HLI holds them
  std::uint32_t homed_axes = 0, homing_required = 0;  // bit j: path axis j (P-AXIS-00277)
};

// Cycle lateness: how long after its deadline each cycle started.
struct Lateness {
  std::uint64_t wakeups = 0;      // deadlines waited for (one per cycle at speed 1)
  std::uint64_t late_cycles = 0;  // woke more than one cycle time after the deadline
  double worst_us = 0;
  double p50_us = 0, p99_us = 0;  // over the whole session
};

// Plain data: nck.so publishes one through HAL shared memory (apps/hal/link.hpp).
struct LiveSnapshot {
  std::uint64_t generation = 0;  // which loaded run (LiveKernel::load)
  std::uint64_t cycle = 0;       // the run's cycles
  double t_s = 0;                // the run's simulated time
  bool paused = false;
  double speed = 1;              // simulated seconds per wall second (0: as fast as possible)
  std::size_t channel_count = 0;
  std::size_t spindle_count = 0;
  std::array<LiveChannel, config::kMaxChannels> channels{};
  std::array<kernel::SpindleOutput, kernel::kMaxMachineSpindles> spindles{};
  std::array<plc::SpindleStatus, kernel::kMaxMachineSpindles> hli_spindles{};
  std::array<double, kernel::kMaxMachineSpindles> spindle_override_pct{};  // the operator's (HLI)
  Lateness lateness;
  std::uint64_t events_lost = 0;  // the event ring was full (a server that fell behind)
  kernel::MachineOutput machine{};  // E-stop and machine on as the kernel follows them
};
static_assert(std::is_trivially_copyable_v<LiveSnapshot>);

// The kernel's channels and spindles after the cycle that gave `out`
// (real-time safe: copies only), not the operator's switches (each channel's
// `hli`, the spindle overrides): their owner fills them. Inline: nck.so
// (apps/hal) fills one in its HAL thread without linking this layer.
inline void fill_kernel_snapshot(const kernel::Kernel& k, const kernel::TickOutput& out, LiveSnapshot& s) noexcept {
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
  }
  s.spindles = out.spindles;
  s.hli_spindles = out.hli_spindles;
}

// The run's channels, spindles and operator switches after the cycle that
// gave `out` (real-time safe: copies only). The fields of the server's own
// (generation, paused, speed, lateness, events_lost) are left as they are.
void fill_snapshot(const sim::DryRun& run, const kernel::TickOutput& out, LiveSnapshot& s) noexcept;

}  // namespace nck::app
