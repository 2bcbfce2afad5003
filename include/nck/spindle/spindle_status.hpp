#pragma once
// What the spindle interpolator reports to the kernel each cycle, and the
// result of a command. Plain data.
#include <cstdint>
#include <string_view>

#include "nck/core/diagnostic.hpp"

namespace nck::spindle {

enum class SpindleMode : std::uint8_t { stop, rotate, position, homing, gear_change, axis, error };

// "stop", "rotate", ... as the events file writes them (`spindle` events' `mode`).
std::string_view mode_name(SpindleMode m) noexcept;

// Outcome of a command: id 0 = accepted; a warning id (SpindleSpeedLimited)
// is accepted too; an error id means the command did nothing, except 60254
// which also puts the spindle into error state (FCT-S1 2.3).
struct SpindleResult {
  ErrorId id{};
  bool warning = false;
  bool ok() const noexcept { return id == ErrorId{} || warning; }
};

struct SpindleStatus {
  SpindleMode mode = SpindleMode::stop;
  double set_rpm = 0;           // signed set-point speed (M3 +, M4 -)
  double set_pos_deg = 0;       // set-point position in [modulo_lower, modulo_upper)
  double act_rpm = 0;           // simulated actual speed
  double act_pos_deg = 0;       // simulated actual position in [modulo_lower, modulo_upper)
  double cmd_rpm = 0;           // speed the spindle runs towards (programmed x override, limited), signed
  double programmed_rpm = 0;    // last programmed speed, signed
  double set_accel_deg_s2 = 0;  // set-point acceleration of the last cycle
  double lag_deg = 0;           // set minus actual position
  double distance_to_go_deg = 0;  // positioning / homing / gear change approach
  double target_pos_deg = 0;    // M19 / homing / change position target
  double override_pct = 100;    // HLI override in force (100 while G167 suppresses it)
  double drive_output = 0;      // speed command value in drive units (antr.v_reso_*)
  std::uint32_t gear_stage = 1;
  ErrorId error{};              // the error that put the spindle into error state
  bool speed_reached = false;   // rotate: actual inside the vb_prozent band; else = standstill
  bool standstill = true;       // set speed 0 and actual below vb_min_null
  bool in_position = false;     // position mode: on target and lag inside the window
  bool homed = false;           // reference known
  bool reference_lost = false;  // control limit (vb_regelgrenze) exceeded since the last homing
  bool gear_change_ready = false;  // at getr_schalt_pos, standing: the PLC may shift
  bool feedhold = false;
};

}  // namespace nck::spindle
