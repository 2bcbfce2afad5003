#include "nck/spindle/spindle_params.hpp"

#include <algorithm>

namespace nck::spindle {

SpindleParams SpindleParams::from(const config::AxisConfig* axis, const config::ChannelSpindle& sp,
                                  const config::SimConfig& sim, double cycle_s) {
  SpindleParams p;
  p.plc_control = sp.plc_control;
  p.cycle_s = cycle_s;
  p.speed_time_constant_s = std::max(0.0, sim.drive_speed_time_constant_s);
  if (axis == nullptr) return p;
  p.gears = axis->gears;
  p.initial_gear = std::clamp<std::uint32_t>(axis->initial_gear_stage, 1, config::kMaxGearStages);
  p.vorz_richtung = axis->vorz_richtung;
  p.beweg_richt_positive = axis->beweg_richt_positive;
  p.vb_prozent_permille = axis->vb_prozent_permille;
  p.no_stop_by_channel_reset = axis->no_stop_by_channel_reset;
  p.open_loop = axis->is_speed_controlled();
  // Of the open-loop modes only the one with position feedback knows where
  // the spindle is; the others (and the seed's sensorless example) cannot
  // position or home.
  p.can_position = !p.open_loop || axis->operation_mode == "OPEN_POSITION_LOOP_POS_FEEDBACK";
  p.feedforward_ta_s = std::max(0.0, axis->feedforward_ta_s);
  p.v_reso_num = axis->v_reso_num;
  p.v_reso_denom = axis->v_reso_denom;
  p.v_time_base = axis->v_time_base;
  return p;
}

}  // namespace nck::spindle
