#include "nck/sim/machine_sim.hpp"

namespace nck::sim {
namespace {

// The probe of channel ch: the channel axis named by sim.lis probe.axis.
Probe make_probe(const config::Machine& m, std::size_t ch) {
  const config::ChannelConfig& c = m.channels[ch];
  if (m.sim.probe_axis.empty()) return Probe{};
  for (std::size_t j = 0; j < c.axes.size(); ++j)
    if (c.axes[j].name == m.sim.probe_axis)
      return Probe{static_cast<int>(j), m.sim.probe_position_mm, c.axes.size()};
  return Probe{};
}

}  // namespace

MachineSim::MachineSim(const config::Machine& m)
    : plc_(m.sim), drives_(m), hli_(plc::make_hli_image(m)), map_(plc::build_spindle_map(m)) {
  channels_ = std::min(m.channels.size(), config::kMaxChannels);
  spindles_ = std::min(map_.count, kernel::kMaxMachineSpindles);
  // A dry run has no operator: unless the scenario says otherwise, every
  // hold is released in the cycle it begins, so M0 costs no time.
  auto_cycle_start_.fill(true);
  for (std::size_t ch = 0; ch < channels_; ++ch) {
    probes_[ch] = make_probe(m, ch);
    sensors_[ch] = DistanceSensor(m.sim, m.channels[ch], m.cycle_time_us * 1e-6);
  }
}

void MachineSim::load_scenario(const sim::Scenario& scenario) {
  player_ = ScenarioPlayer(scenario);
  scenario_ = &scenario;
  // The PLC sets skip levels at time 0 before the program starts: decoding,
  // which runs ahead of the first cycle, sees them from the first block.
  jog_lines_left_ = 0;
  for (const sim::ScenarioAction& a : scenario.actions) {
    if (a.kind == sim::ActionKind::jog || a.kind == sim::ActionKind::jog_increment) ++jog_lines_left_;
    if (a.kind != sim::ActionKind::skip_mask) continue;
    skip_levels_used_ = true;
    if (a.t_s <= 0 && a.channel >= 1 && a.channel <= channels_)
      hli_.channel[a.channel - 1u].skip_mask = static_cast<std::uint32_t>(a.value);
  }
}

void MachineSim::read(double t_s, kernel::TickInput& in) noexcept {
  t_s_ = t_s;
  in.ext_commands.clear();
  in.ext_commands_lost = 0;
  if (handwheel_turned_) {  // last cycle's travel is handed over once
    for (std::size_t ch = 0; ch < channels_; ++ch) in.channels[ch].handwheel_mm.fill(0.0);
    handwheel_turned_ = false;
  }
  if (jogs_given_) {  // a jog request is handed over once
    for (std::size_t ch = 0; ch < channels_; ++ch) in.channels[ch].jogs.clear();
    jogs_given_ = false;
  }
  for (const sim::ScenarioAction& a : player_.due(t_s)) {
    const bool jog = a.kind == sim::ActionKind::jog || a.kind == sim::ActionKind::jog_increment;
    if (jog && jog_lines_left_ > 0) --jog_lines_left_;  // counts the timed lines only
    apply(a, in);
  }
  player_.for_each_triggered_due(t_s, [&](const sim::ScenarioAction& a) { apply(a, in); });
  for (const sim::ScenarioAction& a : operator_actions_) apply(a, in);
  operator_actions_.clear();

  plc_.tick(t_s);
  plc_.drain_acks(acks_);
  in.acks.clear();
  for (const plc::PlcAck& a : acks_) (void)in.acks.push_back(a);  // fits: same capacity

  for (std::size_t ch = 0; ch < channels_; ++ch) {
    plc::ChannelControl& c = hli_.channel[ch];
    kernel::ChannelInput& ci = in.channels[ch];
    ci.feed_override_pct = c.feed_override_percent;
    ci.rapid_override_pct = c.rapid_override_percent;
    ci.feedhold = c.feedhold;
    ci.optional_stop = c.optional_stop;
    ci.reset = c.reset;
    c.reset = false;  // a request: handed over once
    ci.stop_at = stop_at_[ch];
    ci.single_step = c.single_step;
    ci.manual_mode = c.manual_mode;
    // The simulated operator presses cycle start for holds, never in error.
    const bool in_error = hli_.channel_state[ch].program_state == static_cast<std::uint8_t>(kernel::ProgramState::error);
    ci.cycle_start = c.cycle_start || (auto_cycle_start_[ch] && !in_error);
    c.cycle_start = false;
    ci.stop = c.stop;
    c.stop = false;
    ci.probe_switched = probe_switched_[ch];
    if (probe_switched_[ch]) ci.probe_latched_mcs = probes_[ch].latched();
    if (sensor_on_[ch]) sensors_[ch].sample(t_s, ci.dist_sensor_valid, ci.dist_sensor_mm);
    else ci.dist_sensor_valid = false;
  }
  for (std::size_t i = 0; i < spindles_; ++i) {
    in.spindles[i] = hli_.spindle_control[i];
    hli_.spindle_control[i].reset = false;
  }
}

void MachineSim::write(const kernel::TickOutput& out) noexcept {
  for (const kernel::TechRequest& r : out.tech_outputs) (void)plc_.submit(r.handle, r.output, t_s_);
  if (player_.has_triggers())  // lines waiting for a program state ('@hold cycle_start')
    for (const kernel::Event& e : out.events)
      if (const auto* s = e.get<kernel::ev::State>()) player_.entered(e.channel, s->to, out.t_s);
  for (std::size_t ch = 0; ch < channels_; ++ch) {
    write_channel_state(out.channels[ch].program_state, hli_.channel_state[ch]);
    probe_switched_[ch] = probes_[ch].watch(out.channels[ch].axis_mcs);
    sensors_[ch].watch(out.channels[ch].axis_mcs);
  }
}

// The HLI's channel state: the program state, and where a block search is
// (a hold right after the return to the contour waits to continue it).
void MachineSim::write_channel_state(kernel::ProgramState st, plc::ChannelState& hli) noexcept {
  using BS = plc::BlockSearchState;
  const bool waits_after_return = st == kernel::ProgramState::hold &&
                                  (hli.block_search == BS::returning_to_contour ||
                                   hli.block_search == BS::wait_for_continue_contour);
  hli.program_state = static_cast<std::uint8_t>(st);
  hli.block_search = st == kernel::ProgramState::searching   ? BS::active
                     : st == kernel::ProgramState::returning ? BS::returning_to_contour
                     : waits_after_return                    ? BS::wait_for_continue_contour
                                                             : BS::inactive;
}

// One scenario action: the PLC writes its HLI controls, falls silent,
// passes an external spindle command on, or a handwheel is turned.
void MachineSim::apply(const sim::ScenarioAction& a, kernel::TickInput& in) noexcept {
  const std::size_t c = a.channel >= 1 && a.channel <= channels_ ? a.channel - 1u : 0u;
  plc::ChannelControl& ch = hli_.channel[c];
  switch (a.kind) {
    case sim::ActionKind::feed_override: ch.feed_override_percent = a.value; return;
    case sim::ActionKind::rapid_override: ch.rapid_override_percent = a.value; return;
    case sim::ActionKind::feedhold: ch.feedhold = a.on; return;
    case sim::ActionKind::reset: ch.reset = true; return;
    case sim::ActionKind::optional_stop: ch.optional_stop = a.on; return;
    case sim::ActionKind::cycle_start: ch.cycle_start = true; return;
    case sim::ActionKind::stop: ch.stop = true; return;
    case sim::ActionKind::auto_cycle_start: auto_cycle_start_[c] = a.on; return;
    case sim::ActionKind::single_step: ch.single_step = a.on; return;
    case sim::ActionKind::skip_mask:  // from now on preparation reads the levels
      ch.skip_mask = static_cast<std::uint32_t>(a.value);
      skip_levels_used_ = true;
      return;
    case sim::ActionKind::silent: plc_.set_silent(a.on); return;
    case sim::ActionKind::mdi:  // beyond 64 lines due in one cycle: dropped (docs/plc-scenario.md)
      (void)mdi_requests_.push_back(MdiRequest{a.line, a.channel, static_cast<std::uint32_t>(a.value)});
      return;
    case sim::ActionKind::block_search: return;  // taken at setup (DryRunOptions::search)
    case sim::ActionKind::handwheel:
      if (a.axis >= 0) in.channels[c].handwheel_mm[static_cast<std::size_t>(a.axis)] += a.value;
      handwheel_turned_ = true;
      return;
    case sim::ActionKind::jog:
    case sim::ActionKind::jog_increment: apply_jog(a, in.channels[c]); return;
    case sim::ActionKind::mode: ch.manual_mode = a.on; return;
    case sim::ActionKind::variable: {
      auto& vars = in.channels[c].variables;
      for (kernel::ChannelVariable& v : vars)
        if (v.name == a.var_name) {
          v.value = a.value;
          return;
        }
      (void)vars.push_back(kernel::ChannelVariable{a.var_name, a.value});  // beyond 16: ignored
      return;
    }
    case sim::ActionKind::spindle_cmd:
      if (!in.ext_commands.push_back(a.cmd)) ++in.ext_commands_lost;
      return;
    case sim::ActionKind::spindle_stop_at_end:
      if (!a.has_spindle()) {  // every spindle of the channel
        for (std::int32_t i = 0; i < static_cast<std::int32_t>(config::kMaxSpindles); ++i) {
          const std::int8_t h = map_.at(a.channel, i);
          if (h >= 0 && static_cast<std::size_t>(h) < spindles_)
            hli_.spindle_control[static_cast<std::size_t>(h)].stop_at_program_end = a.on;
        }
        return;
      }
      apply_to_spindle(a);
      return;
    default: apply_to_spindle(a); return;
  }
}

// A jog line: the operator presses (or releases) a jog key.
void MachineSim::apply_jog(const sim::ScenarioAction& a, kernel::ChannelInput& in) noexcept {
  using Kind = kernel::JogRequest::Kind;
  kernel::JogRequest r;
  r.axis = a.axis;
  r.direction = a.direction < 0 ? std::int8_t{-1} : std::int8_t{1};
  if (a.kind == sim::ActionKind::jog_increment) {
    r.kind = Kind::increment;
    r.step_mm = a.value;
  } else {
    r.kind = a.direction == 0 ? Kind::stop : Kind::continuous;
    r.speed_mm_s = a.value;
  }
  (void)in.jogs.push_back(r);  // more than kMaxJogRequestsPerTick at one time: the rest is lost
  jogs_given_ = true;
}

void MachineSim::apply_to_spindle(const sim::ScenarioAction& a) noexcept {
  if (a.hli_spindle < 0 || static_cast<std::size_t>(a.hli_spindle) >= spindles_) return;
  plc::SpindleControl& sc = hli_.spindle_control[static_cast<std::size_t>(a.hli_spindle)];
  switch (a.kind) {
    case sim::ActionKind::spindle_override: sc.override_percent = a.value; sc.override_valid = true; return;
    case sim::ActionKind::override_valid: sc.override_valid = a.on; return;
    case sim::ActionKind::spindle_feedhold: sc.feedhold = a.on; return;
    case sim::ActionKind::spindle_stop_at_end: sc.stop_at_program_end = a.on; return;
    case sim::ActionKind::spindle_reset: sc.reset = true; return;
    default: return;
  }
}

}  // namespace nck::sim
