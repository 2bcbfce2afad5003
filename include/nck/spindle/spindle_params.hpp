#pragma once
// The configuration one spindle interpolator needs, copied from the machine
// model at setup so that the cyclic object holds no pointers into it.
#include <array>
#include <cstdint>

#include "nck/config/machine.hpp"

namespace nck::spindle {

struct SpindleParams {
  std::array<config::GearStage, config::kMaxGearStages> gears{};
  std::uint32_t initial_gear = 1;
  bool vorz_richtung = false;
  bool beweg_richt_positive = false;
  double vb_prozent_permille = 100;
  bool no_stop_by_channel_reset = false;
  bool open_loop = false;       // speed-controlled (antr.operation_mode OPEN_POSITION_LOOP*)
  bool can_position = true;     // position feedback present (else 70252 on M19 / G74)
  bool plc_control = false;     // PLC spindle over the channel HLI (no axis list)
  double feedforward_ta_s = 1e-6;
  double speed_time_constant_s = 0.02;  // drive speed lag of a speed-controlled spindle
  std::uint32_t v_reso_num = 1, v_reso_denom = 36, v_time_base = 0;
  double cycle_s = 0.001;
  double in_position_window_deg = 0.01;  // nck's own: no parameter in the seeds

  // Copies the fields of an axis list (null: defaults). // setup
  static SpindleParams from(const config::AxisConfig* axis, const config::ChannelSpindle& sp,
                            const config::SimConfig& sim, double cycle_s);
};

}  // namespace nck::spindle
