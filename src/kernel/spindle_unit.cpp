#include "spindle_unit.hpp"

#include <cmath>

namespace nck::kernel {
namespace {

// An event of the spindle, in the channel that commands it. rt
Event spindle_event(const SpindleUnit& u, double t_s, const EventPayload& p) noexcept {
  return Event{{t_s, u.channel, {}}, p};
}

}  // namespace

void report_spindle_changes(SpindleUnit& u, std::int8_t index, double t_s, TickOutput& out) noexcept {
  // It reads the judged part of the status only (and the speed law): a
  // spindle at a steady speed has nothing new most cycles.
  if (u.axis.judgements() == u.reported_judgements && u.speed_law == u.reported_speed_law) return;
  u.reported_judgements = u.axis.judgements();
  u.reported_speed_law = u.speed_law;
  const spindle::SpindleStatus& s = u.axis.status();
  if (s.mode != u.last_mode || (s.cmd_rpm != u.last_cmd_rpm && !u.speed_law)) {
    const Event e = spindle_event(u, t_s, spindle::ModeEvent{index, s.mode, s.cmd_rpm, s.gear_stage});
    out.emit(e);
    u.last_mode = s.mode;
    u.last_cmd_rpm = s.cmd_rpm;
  }
  const bool reached = s.mode == spindle::SpindleMode::rotate && s.cmd_rpm != 0 && s.speed_reached;
  if (reached && !u.last_speed_reached) {
    const Event e = spindle_event(u, t_s, spindle::SpeedReachedEvent{index, s.act_rpm});
    out.emit(e);
  }
  u.last_speed_reached = reached;
  // No error event here: whoever commanded the spindle reports the failed
  // command (the channel with its line, run_external_commands for the PLC);
  // the error state shows as the spindle event with mode "error".
}

void advance_gear_job(SpindleUnit& u, std::int8_t index, PlcOutputs& plc, double t_s,
                      TickOutput& out) noexcept {
  const std::int32_t m = static_cast<std::int32_t>(39 + u.gear_stage);  // stage 1 = M40
  if (u.gear_job == GearJob::approaching && u.axis.status().gear_change_ready) {
    plc::TechOutput o;
    o.kind = plc::TechKind::m;
    o.number = m;
    o.channel = u.channel;
    o.spindle = u.channel_index;
    o.sync = config::sync::MVS_SVS;
    u.gear_handle = plc.submit(o, out);
    if (u.gear_handle == plc::kNoHandle) {  // tried again next cycle
      if (!u.gear_output_delayed) {
        const Event w = spindle_event(u, t_s, ev::Warning{{ErrorId::KernelPlcOutputsFull, std::nullopt, index}});
        out.emit(w);
      }
      u.gear_output_delayed = true;
      return;
    }
    u.gear_output_delayed = false;
    const Event e = spindle_event(u, t_s, ev::PlcOut{plc::TechKind::m, m, index, 0, config::sync::MVS_SVS});
    out.emit(e);
    u.gear_job = GearJob::shifting;
  } else if (u.gear_job == GearJob::shifting && u.gear_acked) {
    (void)u.axis.finish_gear_change();
    const Event e = spindle_event(u, t_s, spindle::GearEvent{index, u.gear_stage, m});
    out.emit(e);
    u.last_gear = u.gear_stage;
    u.gear_job = GearJob::done;
  }
}

std::optional<double> speed_change_rpm(const SpindleUnit& u, double rpm) noexcept {
  const spindle::SpindleStatus& s = u.axis.status();
  if (s.mode == spindle::SpindleMode::rotate) {
    // Started by the PLC or another channel: its own direction counts.
    const int dir = s.programmed_rpm > 0 ? 1 : s.programmed_rpm < 0 ? -1 : u.rotation_dir;
    return dir * rpm;
  }
  if (s.mode == spindle::SpindleMode::stop && u.rotation_across_gear_change) return u.rotation_dir * rpm;
  return std::nullopt;
}

void note_rotation(SpindleUnit& u, const SpindleAction& a) noexcept {
  const spindle::SpindleStatus& s = u.axis.status();
  switch (a.op) {
    case SpindleOp::gear_change:
      u.rotation_across_gear_change = s.mode == spindle::SpindleMode::rotate;
      if (s.programmed_rpm != 0) u.rotation_dir = s.programmed_rpm > 0 ? 1 : -1;
      return;
    case SpindleOp::rotate:
      u.rotation_dir = a.direction == spindle::Direction::negative ? -1 : 1;
      u.rotation_across_gear_change = false;
      return;
    case SpindleOp::speed:
    case SpindleOp::stop:
    case SpindleOp::position:
    case SpindleOp::home: u.rotation_across_gear_change = false; return;
    default: return;  // G130, G135, tool data... leave the rotation alone
  }
}

void fill_hli_status(const SpindleUnit& u, plc::SpindleStatus& h) noexcept {
  const spindle::SpindleStatus& s = u.axis.status();
  using spindle::SpindleMode;
  namespace bits = plc::spindle_mode;
  switch (s.mode) {
    case SpindleMode::rotate: h.mode_bits = s.cmd_rpm < 0 ? bits::M04 : bits::M03; break;
    case SpindleMode::position: h.mode_bits = bits::M19; break;
    case SpindleMode::homing: h.mode_bits = bits::HOMING; break;
    default: h.mode_bits = bits::M05; break;
  }
  h.nominal_rpm = s.set_rpm;
  h.actual_rpm = s.act_rpm;
  h.programmed_rpm = s.programmed_rpm;
  h.target_pos_deg = s.target_pos_deg;
  h.actual_pos_deg = s.act_pos_deg;
  h.distance_to_go_deg = s.distance_to_go_deg;
  h.gear_stage = static_cast<std::uint8_t>(s.gear_stage);
  h.speed_monitoring_active = s.mode == SpindleMode::rotate;
  h.speed_reached = s.speed_reached;
  h.stopped = s.standstill;
  h.monitoring_invalid = s.reference_lost;
  h.job_error = s.error != ErrorId{};
}

}  // namespace nck::kernel
