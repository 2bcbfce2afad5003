#pragma once
// The data that crosses the cyclic boundary: fixed-size, no heap.
#include <array>
#include <cstdint>

#include "nck/config/machine.hpp"
#include "nck/core/fixed_vector.hpp"
#include "nck/kernel/event.hpp"

namespace nck::kernel {

inline constexpr std::size_t kMaxEventsPerTick = 256;

struct ChannelInput {
  double feed_override_pct = 100;  // HLI feed override 0..100 (more is clamped)
  bool feedhold = false;
  bool reset = false;
};

struct TickInput {
  std::array<ChannelInput, config::kMaxChannels> channels{};
};

enum class ChannelStatus : std::uint8_t { idle, running, waiting, ended, aborted };

struct ChannelOutput {
  AxisArray axis_mcs{};  // set points, mm / deg
  double path_velocity_mm_s = 0;
  double dist_offset_mm = 0;  // 3D distance control's offset on the tool axis (0 while inactive)
  ChannelStatus status = ChannelStatus::idle;
};

inline constexpr std::size_t kMaxMachineSpindles = 32;

struct SpindleOutput {
  double set_rpm = 0;       // signed set-point speed
  double set_pos_deg = 0;   // set-point position in the modulo range
  double act_rpm = 0;       // simulated actual speed
  double drive_output = 0;  // speed command in drive units (antr.v_reso_*)
};

struct TickOutput {
  double t_s = 0;  // start of the cycle just computed
  std::array<ChannelOutput, config::kMaxChannels> channels{};
  std::array<SpindleOutput, kMaxMachineSpindles> spindles{};  // by kernel spindle index
  FixedVector<Event, kMaxEventsPerTick> events;
  std::uint32_t events_dropped = 0;  // events that did not fit this cycle

  // Adds an event, or counts it as dropped when the cycle's list is full. rt
  void emit(const Event& e) noexcept {
    if (!events.push_back(e)) ++events_dropped;
  }
};

}  // namespace nck::kernel
