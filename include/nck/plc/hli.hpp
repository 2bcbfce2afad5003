#pragma once
// The HLI image: the data the CNC and the PLC exchange every cycle (seed
// FCT-S1 §2.4/§2.9; paths as the TF5200 HLI names them). Plain fixed-size
// structs, no heap, so the kernel can read and write them in the cyclic path.
//
// Directions: *Status is written by the CNC and read by the PLC; *Control is
// written by the PLC (or a --plc scenario) and read by the CNC.
#include <array>
#include <cstddef>
#include <cstdint>

#include "nck/config/machine.hpp"

namespace nck::plc {

// Spindle objects exist per spindle axis of the machine, not per channel: a
// spindle known to two channels has one object (see SpindleMap).
inline constexpr std::size_t kMaxHliSpindles = 32;
inline constexpr std::size_t kMaxHliChannels = config::kMaxChannels;
inline constexpr std::int8_t kNoSpindle = -1;

// Operating-state bits of ipo_state.spindle.mode_r (TF5200 HLI).
namespace spindle_mode {
inline constexpr std::uint32_t M05 = 1;
inline constexpr std::uint32_t M03 = 2;
inline constexpr std::uint32_t M04 = 4;
inline constexpr std::uint32_t M19 = 8;
inline constexpr std::uint32_t PLCOPEN = 16;  // superimposed PLCopen motion
inline constexpr std::uint32_t HOMING = 32;
}  // namespace spindle_mode

// CNC -> PLC, one per spindle. Speeds in rpm (signed: M3 +, M4 -), positions
// in degrees; to_hli_speed() / encode_position() give the wire values.
struct SpindleStatus {
  std::uint32_t mode_bits = spindle_mode::M05;
  double nominal_rpm = 0;      // set point (active_rev_r)
  double actual_rpm = 0;       // simulated actual (current_rev_r)
  double programmed_rpm = 0;   // as programmed (cmd_rev_r)
  double target_pos_deg = 0;
  double actual_pos_deg = 0;
  double distance_to_go_deg = 0;
  std::uint8_t gear_stage = 1;            // 1..6
  bool speed_monitoring_active = false;   // rev_control_aktiv_r
  bool speed_reached = false;             // rev_erreicht_r
  bool stopped = true;                    // rev_null_r
  bool monitoring_invalid = false;        // speed monitoring invalid
  bool job_error = false;                 // command error
};

// PLC -> CNC, one per spindle.
struct SpindleControl {
  double override_percent = 100;   // ipo_mc_control.override
  bool override_valid = true;      // ipo_mc_control.override_valid; false = 100 %
  bool feedhold = false;           // axis-specific feedhold of this spindle
  bool stop_at_program_end = false;  // spdl_stop_at_prog_end
  bool reset = false;              // spdl_reset: a request, the CNC clears it when done
  // The override the CNC should apply: 100 % while the PLC has not set valid.
  double effective_override_percent() const noexcept {
    return override_valid ? override_percent : 100.0;
  }
};

// PLC -> CNC, one per channel.
struct ChannelControl {
  double feed_override_percent = 100;
  double rapid_override_percent = 100;  // G0 blocks, as P-CHAN-00181 says
  bool feedhold = false;
  bool reset = false;          // a request, the CNC clears it when it has reset the channel
  bool optional_stop = false;  // M01 stops only while this is on
  bool cycle_start = false;    // a request: releases a program hold (M0 / M1), cleared when handed over
  bool stop = false;           // a request (NC stop): the channel holds where it is, cleared when handed over
  bool single_step = false;    // single step mode (held until switched off)
  bool manual_mode = false;    // mode selection: manual (jog, handwheel without G201) or automatic
  // decoder_mc_control.program_block_ignore: the active block-skip levels,
  // /1 = 0x1 ... /10 = 0x200 (docs/nc-language.md); blocks decoded from then on skip
  std::uint32_t skip_mask = 0;
};

// CNC -> PLC, one per channel: the program state (kernel::ProgramState,
// docs/operating.md) and the block search state (TF5200 HLI bahn_state).
enum class BlockSearchState : std::int16_t {
  inactive = 0,                  // HLI_BS_INACTIVE
  active = 2,                    // HLI_BS_ACTIVE: decoding without motion, functions to the PLC
  returning_to_contour = 5,      // HLI_BS_RETURNING_TO_CONTOUR
  wait_for_continue_contour = 6, // HLI_BS_WAIT_FOR_CONTINUE_CONTOUR: holds for cycle start
};

struct ChannelState {
  std::uint8_t program_state = 0;  // kernel::ProgramState as a number
  BlockSearchState block_search = BlockSearchState::inactive;  // block_search_state_r
  bool block_search_active() const noexcept {  // block_search_active_r
    return block_search == BlockSearchState::active;
  }
};

// A technology function output to the PLC and its handshake.
// The kind of a technology function: one enum from the planned block to the
// PLC and the events (none: an event that carries no function).
enum class TechKind : std::uint8_t { none, m, h, s, t };

struct TechOutput {
  TechKind kind = TechKind::m;
  std::int32_t number = 0;          // M3 -> 3, T5 -> 5; S: 0
  std::uint8_t channel = 1;         // 1-based
  std::int8_t spindle = kNoSpindle; // index into the channel's spindles, or none
  double value = 0;                 // S: rpm; M19: position (deg); M/H: additional value (M52=-345); else 0
  std::uint32_t sync = 0;           // synchronisation bits (config::sync)
};

// One handshake slot as the PLC sees it (techno_unit_*_sync[k]).
struct TechUnit {
  TechOutput output;
  bool please = false;  // CNC: a function waits for the PLC
  bool done = false;    // PLC: acknowledged
};

// The handshake of one technology function: the CNC numbers each output
// (0 is never a valid handle) and the PLC acknowledges it by that number.
using OutputHandle = std::uint32_t;
inline constexpr OutputHandle kNoHandle = 0;

struct PlcAck {
  OutputHandle handle = kNoHandle;
  TechOutput output;
  double t_ack_s = 0;  // time of the cycle that acknowledged it
};

// True for M40..M45 (gear stage 1..6).
constexpr bool is_gear_function(const TechOutput& o) noexcept {
  return o.kind == TechKind::m && o.number >= 40 && o.number <= 45;
}

// A channel's spindle: its channel (1-based) and its index in the channel's list.
struct ChannelSpindleRef {
  std::uint8_t channel = 0;
  std::int8_t index = kNoSpindle;
  bool operator==(const ChannelSpindleRef&) const = default;
};

// Which HLI spindle object belongs to a channel's spindle. Built at setup:
// spindles of all channels in channel order; a spindle that another channel
// already listed (same logical axis number) reuses that object.
struct SpindleMap {
  std::array<std::array<std::int8_t, config::kMaxSpindles>, kMaxHliChannels> index{};
  std::size_t count = 0;  // number of HLI spindle objects in use
  // Each HLI spindle's first listing (the lowest channel, then index): its
  // settings are the ones that count when several channels list it.
  std::array<ChannelSpindleRef, kMaxHliSpindles> first{};
  // HLI index of spindle i of channel ch (1-based), kNoSpindle if none.
  std::int8_t at(std::size_t ch, std::int32_t i) const noexcept {
    if (ch < 1 || ch > kMaxHliChannels || i < 0 || i >= static_cast<std::int32_t>(config::kMaxSpindles))
      return kNoSpindle;
    return index[ch - 1][static_cast<std::size_t>(i)];
  }
};

// setup: extra spindles beyond kMaxHliSpindles get kNoSpindle.
SpindleMap build_spindle_map(const config::Machine& m);

// The PLC's side of the HLI. The spindles' status objects come with each
// cycle's TickOutput (hli_spindles), and kernel::Kernel::hli_spindle_status
// gives them at any time; no copy of them is kept here.
struct HliImage {
  std::array<SpindleControl, kMaxHliSpindles> spindle_control{};
  std::array<ChannelControl, kMaxHliChannels> channel{};
  std::array<ChannelState, kMaxHliChannels> channel_state{};
  bool ads_32_bit_comp_mode = true;  // P-STUP-00175, decides the position format
};

// setup: an image with the initial overrides of sim.lis.
HliImage make_hli_image(const config::Machine& m);

// ---- wire encodings ---------------------------------------------------------
// P-STUP-00175: 1 = positions as 32-bit values scaled to the list unit
// (0.0001 deg for rotary axes and spindles, 0.1 um for linear axes);
// 0 = 64-bit high-resolution values, 1000 times finer (1e-7 deg, 0.1 nm).
enum class PositionFormat : std::uint8_t { scaled_32bit, high_res_64bit };

inline constexpr double kScaled32UnitsPerDeg = 1e4;
inline constexpr double kHighRes64UnitsPerDeg = 1e7;

constexpr PositionFormat position_format(bool ads_32_bit_comp_mode) noexcept {
  return ads_32_bit_comp_mode ? PositionFormat::scaled_32bit : PositionFormat::high_res_64bit;
}

struct HliPosition {
  std::int64_t raw = 0;    // fits in int32 when the format is scaled_32bit
  bool saturated = false;  // the value did not fit (or was not finite) and was clamped
};

// rt: position in deg (or mm) to the wire value, rounded to nearest.
HliPosition encode_position(double pos_deg, PositionFormat f) noexcept;
// rt: wire value back to deg (or mm).
double decode_position(std::int64_t raw, PositionFormat f) noexcept;
// rt: speed in rpm to the HLI speed unit 0.001 deg/s (DINT), saturating.
std::int32_t to_hli_speed(double rpm) noexcept;

}  // namespace nck::plc
