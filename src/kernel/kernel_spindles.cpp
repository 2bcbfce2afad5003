// The kernel's per-cycle work besides the channels: the PLC's inputs
// (acknowledgements, spindle controls, external spindle commands) and the
// spindles.
#include "nck/kernel/kernel.hpp"

#include "channel.hpp"
#include "spindle_unit.hpp"

namespace nck::kernel {

void Kernel::take_acknowledgements(const TickInput& in, double t_s, TickOutput& out) noexcept {
  for (const plc::PlcAck& a : in.acks) {
    plc_outputs_->acknowledged();
    const std::int8_t spindle = spindle_map_.at(a.output.channel, a.output.spindle);
    out.emit(Event{{t_s, a.output.channel, {}}, ev::PlcAck{a.output.kind, a.output.number, ev::spindle_or_none(spindle)}});
    for (auto& c : channels_) c->on_ack(a.handle);
    for (SpindleUnit& u : spindles_)
      if (u.gear_handle == a.handle) u.gear_acked = true;
  }
}

// The HLI's spindle controls: override, feedhold, reset request.
void Kernel::take_spindle_controls(const TickInput& in) noexcept {
  for (std::size_t i = 0; i < spindles_.size(); ++i) {
    const plc::SpindleControl& c = in.spindles[i];
    spindles_[i].axis.set_override_pct(c.effective_override_percent());
    spindles_[i].axis.set_feedhold(c.feedhold);
    if (c.reset) spindles_[i].axis.reset();
  }
}

// A real machine's measured spindle values, taken at the start of the
// cycle so that the channels judge the freshest ones: a CiA 402 drive's
// actual values, else the spindle's own measured inputs.
void Kernel::take_spindle_measured(const TickInput& in) noexcept {
  if (drives_ != nullptr) return;  // the attached drives answer in tick_spindles
  for (std::size_t i = 0; i < spindles_.size(); ++i) {
    SpindleUnit& u = spindles_[i];
    if (!take_spindle_drive(u, in)) {
      const spindle::DriveFeedback& m = in.spindle_measured[i];
      if (m.valid || u.axis.feedback().valid) u.axis.take_feedback(m);
    }
    u.machine_measured = u.axis.feedback().valid;
  }
}

void Kernel::take_external_commands(const TickInput& in, double t_s, TickOutput& out) noexcept {
  std::uint32_t lost = in.ext_commands_lost;
  std::uint8_t channel = 1;
  for (const plc::ExtSpindleCommand& cmd : in.ext_commands) {
    if (ext_commands_.push(cmd) != 0) continue;
    ++lost;
    channel = cmd.channel;
  }
  if (lost == 0) return;
  out.emit(Event{{t_s, channel, {}}, ev::Warning{{ErrorId::PlcExtCommandQueueFull, {}, {}}}});
}

namespace {

// True when the spindle has done what its external command asked for
// (speed reached / in position / standstill), or failed at it. rt
bool external_command_done(const SpindleUnit& u) noexcept {
  const spindle::SpindleStatus& s = u.axis.status();
  if (s.mode == spindle::SpindleMode::error) return true;
  return s.mode == spindle::SpindleMode::rotate     ? s.speed_reached
         : s.mode == spindle::SpindleMode::position ? s.in_position
                                                    : s.standstill;
}

void acknowledge_external_command(SpindleUnit& u, std::int8_t index, plc::ExtCommandQueue& queue, double t_s,
                                  TickOutput& out) noexcept {
  queue.acknowledge(u.ext_seq);
  u.ext_seq = 0;
  out.emit(Event{{t_s, u.channel, {}}, ev::PlcAck{plc::TechKind::m, u.ext_m, index}});  // the PLC learns that its command is done
}

void start_external_command(SpindleUnit& u, std::int8_t index, double t_s, TickOutput& out) noexcept {
  const plc::ExtSpindleCommand cmd = u.ext_waiting.front();
  u.ext_waiting.pop();
  spindle::SpindleResult r;
  switch (cmd.fn) {
    case plc::ExtFunction::m3: r = u.axis.rotate(cmd.rev_rpm); break;
    case plc::ExtFunction::m4: r = u.axis.rotate(-cmd.rev_rpm); break;
    case plc::ExtFunction::m5: r = u.axis.stop(); break;
    case plc::ExtFunction::m19: r = u.axis.position(cmd.pos_deg, spindle::Direction::none, cmd.rev_rpm); break;
  }
  u.ext_seq = cmd.seq;
  u.channel = cmd.channel;
  u.ext_m = static_cast<std::int32_t>(cmd.fn);  // the enum's values are the M numbers
  if (r.ok()) return;
  out.emit(Event{{t_s, cmd.channel, {}}, ev::Error{{r.id, std::nullopt, index}}});
}

}  // namespace

// External spindle commands keep their order of arrival per spindle: a
// spindle's next command starts when its last one is done and acknowledged,
// while the other spindles go on with theirs (TF5200 HLI ext_to_ipo: jobs
// run in order of arrival, docs/plc-scenario.md; a job to S1 does not wait
// for S2's speed).
void Kernel::run_external_commands(double t_s, TickOutput& out) noexcept {
  hand_out_external_commands();
  for (std::size_t i = 0; i < spindles_.size(); ++i) {
    SpindleUnit& u = spindles_[i];
    const auto index = static_cast<std::int8_t>(i);
    if (u.ext_seq != 0 && external_command_done(u)) acknowledge_external_command(u, index, ext_commands_, t_s, out);
    if (u.ext_seq == 0 && !u.ext_waiting.empty()) start_external_command(u, index, t_s, out);
  }
}

// Moves the arrived commands, oldest first, to the queues of their spindles;
// a full spindle queue holds back the rest so that no order is broken.
void Kernel::hand_out_external_commands() noexcept {
  plc::ExtSpindleCommand cmd;
  while (!ext_commands_.empty()) {
    const plc::ExtSpindleCommand& next = ext_commands_.front();
    const std::int8_t k = spindle_map_.at(next.channel, next.spindle);
    const bool known = k >= 0 && static_cast<std::size_t>(k) < spindles_.size();
    if (known && spindles_[static_cast<std::size_t>(k)].ext_waiting.full()) return;
    (void)ext_commands_.pop(cmd);
    if (known) (void)spindles_[static_cast<std::size_t>(k)].ext_waiting.push(cmd);
  }
}

void Kernel::tick_spindles(double t_s, TickOutput& out) noexcept {
  for (std::size_t i = 0; i < spindles_.size(); ++i) {
    SpindleUnit& u = spindles_[i];
    const auto idx = static_cast<std::int8_t>(i);
    advance_gear_job(u, idx, *plc_outputs_, t_s, out);
    // A drive that answers within the cycle judges this cycle's set point at
    // once (and refreshes the status); a real one answers with the next
    // TickInput (take_spindle_measured), until then its last values stand.
    const bool moved = u.axis.tick(cycle_s_, drives_ == nullptr);
    const spindle::DriveCommand cmd = u.axis.drive_command();
    if (moved && drives_ != nullptr) u.axis.take_feedback(drives_->step(i, cmd));
    report_spindle_changes(u, idx, t_s, out);
    fill_hli_status(u, out.hli_spindles[i]);
    const spindle::SpindleStatus& s = u.axis.status();
    out.spindles[i] = {s.set_rpm, s.set_pos_deg, s.act_rpm, s.drive_output, cmd};
  }
}

}  // namespace nck::kernel
