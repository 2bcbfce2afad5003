#pragma once
// The CiA 402 drive profile (IEC 61800-7-201; the profile of EtherCAT and
// CANopen drives): the power state machine both sides run, as bits.
//
// The drive reports its state in the statusword (object 0x6041) and
// follows commands in the controlword (0x6040). `Master` is the NC's side
// (what nck writes so that an axis reaches "operation enabled", clears a
// fault, or shuts down), `Device` the drive's side (the simulated drive,
// and tests). Both are plain values stepped once per cycle: no allocation,
// no exception, no clock (the cycle count is the clock).
#include <cstdint>
#include <string_view>

namespace nck::drives::cia402 {

// The power states of the drive state machine.
enum class State : std::uint8_t {
  not_ready_to_switch_on,
  switch_on_disabled,
  ready_to_switch_on,
  switched_on,
  operation_enabled,
  quick_stop_active,
  fault_reaction_active,
  fault,
};
std::string_view name(State s) noexcept;

// Statusword bits (0x6041).
namespace sw {
inline constexpr std::uint16_t ready_to_switch_on = 1u << 0;
inline constexpr std::uint16_t switched_on = 1u << 1;
inline constexpr std::uint16_t operation_enabled = 1u << 2;
inline constexpr std::uint16_t fault = 1u << 3;
inline constexpr std::uint16_t voltage_enabled = 1u << 4;
inline constexpr std::uint16_t quick_stop = 1u << 5;  // 0: a quick stop is active
inline constexpr std::uint16_t switch_on_disabled = 1u << 6;
inline constexpr std::uint16_t warning = 1u << 7;
inline constexpr std::uint16_t remote = 1u << 9;
inline constexpr std::uint16_t target_reached = 1u << 10;
inline constexpr std::uint16_t homing_attained = 1u << 12;  // in homing mode (6)
inline constexpr std::uint16_t homing_error = 1u << 13;     // in homing mode (6)
}  // namespace sw

// Controlword bits (0x6040) and the commands the profile defines.
namespace cw {
inline constexpr std::uint16_t switch_on_bit = 1u << 0;
inline constexpr std::uint16_t enable_voltage_bit = 1u << 1;
inline constexpr std::uint16_t quick_stop_bit = 1u << 2;  // 0: quick stop
inline constexpr std::uint16_t enable_operation_bit = 1u << 3;
inline constexpr std::uint16_t homing_start_bit = 1u << 4;  // homing mode (6): starts on its rising edge
inline constexpr std::uint16_t fault_reset_bit = 1u << 7;  // acts on its rising edge

inline constexpr std::uint16_t shutdown = 0x0006;
inline constexpr std::uint16_t switch_on = 0x0007;  // also "disable operation"
inline constexpr std::uint16_t enable_operation = 0x000F;
inline constexpr std::uint16_t disable_voltage = 0x0000;
inline constexpr std::uint16_t quick_stop = 0x0002;
inline constexpr std::uint16_t fault_reset = 0x0080;
}  // namespace cw

// Modes of operation (0x6060 / 0x6061) nck uses.
enum class Mode : std::int8_t {
  none = 0,
  profile_position = 1,
  profile_velocity = 3,
  homing = 6,
  cyclic_sync_position = 8,  // path axes, position-controlled spindles
  cyclic_sync_velocity = 9,  // speed-controlled spindles
  cyclic_sync_torque = 10,
};

// The state a statusword reports (the profile's bit masks).
State decode(std::uint16_t statusword) noexcept;
// The state bits of a statusword that reports s (remote set; the other
// bits, e.g. target reached, are the caller's).
std::uint16_t statusword_bits(State s) noexcept;

// The NC's side: what to write so that the drive reaches the goal.
enum class Goal : std::uint8_t {
  disabled,   // no voltage: switch on disabled (after a fault: reset it first)
  enabled,    // operation enabled: the drive follows its set points
  quick_stop, // the drive brakes with its quick-stop deceleration and stays there
};

class Master {
 public:
  // The controlword for this cycle, given the state the drive reports.
  // A fault is reset only when the goal asks for power (enabled); the
  // reset is an edge: bit 7 is written for one cycle, cleared the next.
  std::uint16_t controlword(State now, Goal goal) noexcept;
  // Cycles since the goal last changed without being reached (0 when it
  // is reached): the caller turns a limit into an error with its ID.
  std::uint32_t waiting_cycles() const noexcept { return waiting_; }

 private:
  Goal goal_ = Goal::disabled;
  std::uint16_t last_ = cw::disable_voltage;
  std::uint32_t waiting_ = 0;
};

// The drive's side: the state machine a controlword drives (the simulated
// drive). A fault input (amplifier fault, following error) moves it to
// fault reaction, which ends in fault after `fault_reaction_cycles`.
class Device {
 public:
  explicit Device(std::uint32_t fault_reaction_cycles = 1) noexcept : reaction_cycles_(fault_reaction_cycles) {}
  // One cycle: applies the controlword (and a fault, when `fault` is set)
  // and returns the statusword's state bits.
  std::uint16_t step(std::uint16_t controlword, bool fault) noexcept;
  State state() const noexcept { return state_; }

 private:
  State state_ = State::not_ready_to_switch_on;
  std::uint16_t last_controlword_ = 0;
  std::uint32_t reaction_cycles_;
  std::uint32_t reaction_left_ = 0;
};

}  // namespace nck::drives::cia402
