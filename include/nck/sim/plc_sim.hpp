#pragma once
// A simulated PLC: it takes the technology functions the CNC outputs (M, H,
// S, T), acknowledges each after the delay sim.lis configures, performs gear
// changes (M40..M45) in gear_change_time, and can be told to stay silent so
// that the kernel's acknowledgement timeout fires.
//
// The CNC numbers its outputs (plc::OutputHandle); the simulated PLC
// acknowledges them by that number.
//
// Real-time contract: the constructor copies the configuration into fixed
// tables; submit(), tick(), acknowledged(), release() and drain_acks() never
// allocate, lock or throw.
#include <array>
#include <cstddef>
#include <cstdint>

#include "nck/config/machine.hpp"
#include "nck/core/fixed_vector.hpp"
#include "nck/plc/hli.hpp"

namespace nck::sim {

using plc::kNoHandle;
using plc::OutputHandle;
using plc::PlcAck;
using plc::TechOutput;

class PlcSim {
 public:
  static constexpr std::size_t kCapacity = 64;   // outputs waiting at one time
  static constexpr std::size_t kMaxMNumber = 1000;
  using AckList = FixedVector<PlcAck, kCapacity>;

  // setup
  explicit PlcSim(const config::SimConfig& sim);
  // setup: channel ch (1-based) shifts no gears (main_spindle_gear_change
  // 0): its M40..M45 are free M functions, acknowledged as any other.
  void set_free_gear_functions(std::uint8_t ch) noexcept;

  // rt: hands output h to the PLC at time now_s (the cycle start). False
  // when kCapacity outputs are already waiting or h is kNoHandle (the kernel
  // never has more than kCapacity outputs outstanding).
  bool submit(OutputHandle h, const TechOutput& out, double now_s) noexcept;

  // rt: acknowledges every output whose delay has elapsed at now_s, i.e. in
  // the first tick with now_s >= submit time + delay (to the cycle).
  void tick(double now_s) noexcept;

  // rt: true once h has been acknowledged and until it is drained/released.
  bool acknowledged(OutputHandle h) const noexcept;
  // rt: true while h waits for its acknowledgement.
  bool pending(OutputHandle h) const noexcept;
  // rt: frees the slot of h (acknowledged or not: an aborted wait).
  void release(OutputHandle h) noexcept;
  // rt: moves every acknowledged output, oldest first, into out and frees
  // their slots. Returns how many were moved (out is cleared first).
  std::size_t drain_acks(AckList& out) noexcept;
  // rt: forgets every output (CNC reset).
  void clear() noexcept;

  // rt: a silent PLC acknowledges nothing; switching it off acknowledges the
  // overdue outputs at the next tick.
  void set_silent(bool on) noexcept { silent_ = on; }
  bool silent() const noexcept { return silent_; }

  // The delay the PLC takes for out (per M number > gear/tool/spindle > default).
  double ack_delay_s(const TechOutput& out) const noexcept;

  // Gear stage (1..6) the PLC has shifted spindle i of channel ch to; 0 while
  // it has never shifted that spindle (the kernel keeps its own initial stage).
  std::uint8_t gear_stage(std::uint8_t ch, std::int8_t spindle) const noexcept;
  // True while a gear change (M40..M45) of that spindle is in progress.
  bool gear_changing(std::uint8_t ch, std::int8_t spindle) const noexcept;

  std::size_t waiting() const noexcept;  // outputs not yet acknowledged

 private:
  struct Slot {
    OutputHandle handle = kNoHandle;  // kNoHandle = free
    TechOutput output;
    double due_s = 0;
    double t_ack_s = 0;
    bool acked = false;
  };
  Slot* find(OutputHandle h) noexcept;
  const Slot* find(OutputHandle h) const noexcept;
  void on_ack(const Slot& s) noexcept;
  bool shifts_gear(const TechOutput& out) const noexcept;
  void free_slot(Slot& s) noexcept;

  std::array<Slot, kCapacity> slots_{};
  std::array<double, kMaxMNumber> m_delay_s_{};  // < 0: not configured
  double default_delay_s_ = 0, spindle_delay_s_ = 0, tool_delay_s_ = 0, gear_delay_s_ = 0;
  std::array<std::array<std::uint8_t, config::kMaxSpindles>, plc::kMaxHliChannels> gear_{};
  std::array<bool, plc::kMaxHliChannels> free_gear_{};  // per channel: M40..M45 are free
  bool silent_ = false;
  // Slots in use and of those acknowledged: the cyclic calls skip the scan
  // of all kCapacity slots when there is nothing to do.
  std::size_t used_ = 0;
  std::size_t acked_ = 0;
};

}  // namespace nck::sim
