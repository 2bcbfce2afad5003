// The kernel's per-cycle work besides the channels: the PLC (scenario,
// acknowledgements), external spindle commands, and the spindles.
#include "nck/kernel/kernel.hpp"

#include "channel.hpp"
#include "kernel_plc.hpp"
#include "spindle_unit.hpp"

namespace nck::kernel {

void Kernel::tick_plc(double t_s, TickOutput& out) noexcept {
  KernelPlc& p = *plc_;
  for (const plc::ScenarioAction& a : p.player.due(t_s)) {
    if (a.kind == plc::ActionKind::handwheel && a.channel >= 1 && a.channel <= channels_.size())
      channels_[a.channel - 1u]->handwheel(a.axis, a.value);
    if (plc::apply(a, p.map, p.hli, p.sim, p.ext) == plc::ApplyResult::ext_queue_full) {
      Event e;
      e.t_s = t_s;
      e.kind = EventKind::warning;
      e.id = ErrorId::PlcExtCommandQueueFull;
      e.message_index = kNoMessage;
      out.emit(e);
    }
  }
  p.sim.tick(t_s);
  p.acks.clear();
  p.sim.drain_acks(p.acks);
  for (const plc::PlcAck& a : p.acks) {
    Event e;
    e.t_s = t_s;
    e.channel = a.output.channel;
    e.kind = EventKind::plc_ack;
    e.fn = function_kind(a.output.kind);
    e.fn_number = a.output.number;
    e.spindle = p.map.at(a.output.channel, a.output.spindle);
    out.emit(e);
    for (auto& c : channels_) c->on_ack(a.handle);
    for (SpindleUnit& u : spindles_)
      if (u.gear_handle == a.handle) u.gear_acked = true;
    p.sim.release(a.handle);
  }
  // Spindle controls of the HLI: override, feedhold, reset.
  for (std::size_t i = 0; i < spindles_.size(); ++i) {
    plc::SpindleControl& c = p.hli.spindle_control[i];
    spindles_[i].axis.set_override_pct(c.effective_override_percent());
    spindles_[i].axis.set_feedhold(c.feedhold);
    if (c.reset) {
      spindles_[i].axis.reset();
      c.reset = false;
    }
  }
}

// External spindle commands run in order of arrival, one at a time per
// spindle; each is acknowledged when the spindle has done it.
void Kernel::tick_external_commands(double t_s, TickOutput& out) noexcept {
  KernelPlc& p = *plc_;
  for (std::size_t i = 0; i < spindles_.size(); ++i) {
    SpindleUnit& u = spindles_[i];
    if (u.ext_seq == 0) continue;
    const spindle::SpindleStatus& s = u.axis.status();
    const bool done = s.mode == spindle::SpindleMode::rotate ? s.speed_reached
                      : s.mode == spindle::SpindleMode::position ? s.in_position
                                                                 : s.standstill;
    if (!done && s.mode != spindle::SpindleMode::error) continue;
    p.ext.acknowledge(u.ext_seq);
    u.ext_seq = 0;
    Event e;  // the PLC learns that its command is done
    e.t_s = t_s;
    e.channel = u.channel;
    e.kind = EventKind::plc_ack;
    e.fn = FunctionKind::m;
    e.fn_number = u.ext_m;
    e.spindle = static_cast<std::int8_t>(i);
    out.emit(e);
  }
  // Strictly in order of arrival: the next command waits until the last one is done.
  for (const SpindleUnit& u : spindles_)
    if (u.ext_seq != 0) return;
  plc::ExtSpindleCommand cmd;
  if (!p.ext.pop(cmd)) return;
  const std::int8_t k = p.map.at(cmd.channel, cmd.spindle);
  if (k < 0 || static_cast<std::size_t>(k) >= spindles_.size()) return;
  SpindleUnit& u = spindles_[static_cast<std::size_t>(k)];
  spindle::SpindleResult r;
  switch (cmd.fn) {
    case plc::ExtFunction::m3: r = u.axis.rotate(cmd.rev_rpm); break;
    case plc::ExtFunction::m4: r = u.axis.rotate(-cmd.rev_rpm); break;
    case plc::ExtFunction::m5: r = u.axis.stop(); break;
    case plc::ExtFunction::m19:
      r = u.axis.position(cmd.pos_deg, spindle::Direction::none, cmd.rev_rpm);
      break;
  }
  u.ext_seq = cmd.seq;
  u.channel = cmd.channel;
  u.ext_m = cmd.fn == plc::ExtFunction::m3   ? 3
            : cmd.fn == plc::ExtFunction::m4 ? 4
            : cmd.fn == plc::ExtFunction::m5 ? 5
                                             : 19;
  if (!r.ok()) {
    Event e;
    e.t_s = t_s;
    e.channel = cmd.channel;
    e.kind = EventKind::error;
    e.id = r.id;
    e.message_index = kNoMessage;
    e.spindle = k;
    out.emit(e);
  }
}

void Kernel::tick_spindles(double t_s, TickOutput& out) noexcept {
  KernelPlc& p = *plc_;
  for (std::size_t i = 0; i < spindles_.size(); ++i) {
    SpindleUnit& u = spindles_[i];
    const auto idx = static_cast<std::int8_t>(i);
    advance_gear_job(u, idx, p.sim, t_s, out);
    u.axis.tick(cycle_s_);
    report_spindle_changes(u, idx, t_s, out);
    fill_hli_status(u, p.hli.spindle_status[i]);
    const spindle::SpindleStatus& s = u.axis.status();
    out.spindles[i] = {s.set_rpm, s.set_pos_deg, s.act_rpm, s.drive_output};
  }
}

}  // namespace nck::kernel
