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
    : plc_(m.sim),
      drives_(m),
      drive_models_(m),
      hli_(plc::make_hli_image(m)),
      map_(plc::build_spindle_map(m)),
      home_cams_(m) {
  channels_ = std::min(m.channels.size(), config::kMaxChannels);
  spindles_ = std::min(map_.count, kernel::kMaxMachineSpindles);
  // A dry run has no operator: unless the scenario says otherwise, every
  // hold is released in the cycle it begins, so M0 costs no time.
  auto_cycle_start_.fill(true);
  for (std::size_t ch = 0; ch < channels_; ++ch) {
    probes_[ch] = make_probe(m, ch);
    sensors_[ch] = DistanceSensor(m.sim, m.channels[ch], m.cycle_time_us * 1e-6);
    if (!m.channels[ch].main_spindle_gear_change) plc_.set_free_gear_functions(static_cast<std::uint8_t>(ch + 1));
  }
}

void MachineSim::load_scenario(const sim::Scenario& scenario) {
  player_ = ScenarioPlayer(scenario);
  scenario_ = &scenario;
  // The PLC sets skip levels at time 0 before the program starts: decoding,
  // which runs ahead of the first cycle, sees them from the first block.
  jog_lines_left_ = 0;
  for (const sim::ScenarioAction& a : scenario.actions) {
    if (a.kind() == sim::ActionKind::jog || a.kind() == sim::ActionKind::jog_increment) ++jog_lines_left_;
    const auto* skip = a.get<act::SkipMask>();
    if (!skip) continue;
    skip_levels_used_ = true;
    if (a.t_s <= 0 && a.channel >= 1 && a.channel <= channels_) hli_.channel[a.channel - 1u].skip_mask = skip->mask;
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
    const bool jog = a.kind() == sim::ActionKind::jog || a.kind() == sim::ActionKind::jog_increment;
    if (jog && jog_lines_left_ > 0) --jog_lines_left_;  // counts the timed lines only
    apply(a, in);
  }
  player_.for_each_triggered_due(t_s, [&](const sim::ScenarioAction& a) { apply(a, in); });
  for (const sim::ScenarioAction& a : operator_actions_) apply(a, in);
  operator_actions_.clear();

  in.machine = machine_;
  in.axes = axes_;
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
    // Nor while E-stop or machine off refuses starts (each press would be refused).
    const bool refused = machine_.estop || !machine_.machine_on || amp_fault_;
    ci.cycle_start = c.cycle_start || (auto_cycle_start_[ch] && !in_error && !refused);
    c.cycle_start = false;
    ci.stop = c.stop;
    c.stop = false;
    ci.probe_switched = probe_switched_[ch];
    if (probe_switched_[ch]) ci.probe_latched_mcs = probes_[ch].latched();
    if (sensor_on_[ch]) sensors_[ch].sample(t_s, ci.dist_sensor_valid, ci.dist_sensor_mm);
    else ci.dist_sensor_valid = false;
  }
  drive_models_.read(in);
  for (std::size_t i = 0; i < spindles_; ++i) {
    in.spindles[i] = hli_.spindle_control[i];
    hli_.spindle_control[i].reset = false;
  }
}

void MachineSim::write(const kernel::TickOutput& out) noexcept {
  drive_models_.write(out);
  home_cams_.watch(out, axes_);
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

namespace {

// The payload of an action whose kind() was checked.
template <class T>
const T& as(const sim::ScenarioAction& a) noexcept {
  return *a.get<T>();
}

}  // namespace

// One scenario action: the PLC writes its HLI controls, falls silent,
// passes an external spindle command on, or a handwheel is turned.
void MachineSim::apply(const sim::ScenarioAction& a, kernel::TickInput& in) noexcept {
  using K = sim::ActionKind;
  const std::size_t c = a.channel >= 1 && a.channel <= channels_ ? a.channel - 1u : 0u;
  plc::ChannelControl& ch = hli_.channel[c];
  switch (a.kind()) {
    case K::feed_override: ch.feed_override_percent = as<act::FeedOverride>(a).percent; return;
    case K::rapid_override: ch.rapid_override_percent = as<act::RapidOverride>(a).percent; return;
    case K::feedhold: ch.feedhold = as<act::Feedhold>(a).on; return;
    case K::reset: ch.reset = true; return;
    case K::optional_stop: ch.optional_stop = as<act::OptionalStop>(a).on; return;
    case K::cycle_start: ch.cycle_start = true; return;
    case K::stop: ch.stop = true; return;
    case K::auto_cycle_start: auto_cycle_start_[c] = as<act::AutoCycleStart>(a).on; return;
    case K::single_step: ch.single_step = as<act::SingleStep>(a).on; return;
    case K::skip_mask:  // from now on preparation reads the levels
      ch.skip_mask = as<act::SkipMask>(a).mask;
      skip_levels_used_ = true;
      return;
    case K::silent: plc_.set_silent(as<act::Silent>(a).on); return;
    case K::mdi:  // beyond 64 lines due in one cycle: dropped (docs/plc-scenario.md)
      (void)mdi_requests_.push_back(MdiRequest{a.line, a.channel, as<act::Mdi>(a).text});
      return;
    case K::block_search: return;  // taken at setup (DryRunOptions::search)
    case K::handwheel: {
      const act::Handwheel& h = as<act::Handwheel>(a);
      if (h.axis.index >= 0) in.channels[c].handwheel_mm[static_cast<std::size_t>(h.axis.index)] += h.distance_mm;
      handwheel_turned_ = true;
      return;
    }
    case K::jog: push_jog(jog_request(as<act::Jog>(a)), in.channels[c]); return;
    case K::jog_increment: push_jog(jog_request(as<act::JogIncrement>(a)), in.channels[c]); return;
    case K::mode: ch.manual_mode = as<act::Mode>(a).manual; return;
    case K::drive_fault: {
      const act::DriveFault& f = as<act::DriveFault>(a);
      if (f.axis.index >= 0) drive_models_.set_fault(c, static_cast<std::size_t>(f.axis.index), f.on);
      return;
    }
    case K::estop: machine_.estop = as<act::Estop>(a).on; return;
    case K::machine_on: machine_.machine_on = as<act::MachineOn>(a).on; return;
    case K::amp_fault: set_axis_input(c, as<act::AmpFault>(a).axis, &kernel::AxisSwitches::amp_fault, as<act::AmpFault>(a).on); return;
    case K::limit_switch: {
      const act::LimitSwitch& l = as<act::LimitSwitch>(a);
      set_axis_input(c, l.axis, l.direction < 0 ? &kernel::AxisSwitches::neg_limit : &kernel::AxisSwitches::pos_limit, l.on);
      return;
    }
    case K::variable: set_variable(as<act::Variable>(a), in.channels[c]); return;
    case K::spindle_cmd:
      if (!in.ext_commands.push_back(as<act::SpindleCmd>(a).cmd)) ++in.ext_commands_lost;
      return;
    default: apply_to_spindle(a); return;
  }
}

void MachineSim::set_axis_input(std::size_t ch, const act::AxisRef& axis, bool kernel::AxisSwitches::*input,
                                bool on) noexcept {
  const std::int16_t m = axis.spindle_axis_list >= 0 ? axis.spindle_axis_list
                         : axis.index >= 0           ? drive_models_.machine_axis(ch, static_cast<std::size_t>(axis.index))
                                                     : std::int16_t{-1};
  if (m >= 0 && static_cast<std::size_t>(m) < axes_.size()) axes_[static_cast<std::size_t>(m)].*input = on;
  amp_fault_ = false;
  for (const kernel::AxisSwitches& s : axes_) amp_fault_ = amp_fault_ || s.amp_fault;
}

void MachineSim::set_variable(const act::Variable& v, kernel::ChannelInput& in) noexcept {
  for (kernel::ChannelVariable& known : in.variables)
    if (known.name == v.name) {
      known.value = v.value;
      return;
    }
  (void)in.variables.push_back(kernel::ChannelVariable{v.name, v.value});  // beyond 16: ignored
}

// A jog line: the operator presses (or releases) a jog key.
kernel::JogRequest MachineSim::jog_request(const act::Jog& j) noexcept {
  kernel::JogRequest r;
  r.axis = j.axis.index;
  r.direction = j.direction < 0 ? std::int8_t{-1} : std::int8_t{1};
  r.kind = j.direction == 0 ? kernel::JogRequest::Kind::stop : kernel::JogRequest::Kind::continuous;
  r.speed_mm_s = j.speed_mm_min / 60.0;  // 0: the axis's jog speed
  return r;
}

kernel::JogRequest MachineSim::jog_request(const act::JogIncrement& j) noexcept {
  kernel::JogRequest r;
  r.axis = j.axis.index;
  r.direction = j.direction < 0 ? std::int8_t{-1} : std::int8_t{1};
  r.kind = kernel::JogRequest::Kind::increment;
  r.step_mm = j.step_mm;
  return r;
}

void MachineSim::push_jog(const kernel::JogRequest& r, kernel::ChannelInput& in) noexcept {
  (void)in.jogs.push_back(r);  // more than kMaxJogRequestsPerTick at one time: the rest is lost
  jogs_given_ = true;
}

plc::SpindleControl* MachineSim::spindle_control(const act::SpindleRef& s) noexcept {
  if (s.hli < 0 || static_cast<std::size_t>(s.hli) >= spindles_) return nullptr;
  return &hli_.spindle_control[static_cast<std::size_t>(s.hli)];
}

// The actions on one spindle's HLI controls (spindle_stop_at_end without a
// spindle: on every spindle of the channel).
void MachineSim::apply_to_spindle(const sim::ScenarioAction& a) noexcept {
  if (const auto* stop = a.get<act::SpindleStopAtEnd>(); stop && !stop->spindle.given()) {
    for (std::int32_t i = 0; i < static_cast<std::int32_t>(config::kMaxSpindles); ++i) {
      const std::int8_t h = map_.at(a.channel, i);
      if (h >= 0 && static_cast<std::size_t>(h) < spindles_)
        hli_.spindle_control[static_cast<std::size_t>(h)].stop_at_program_end = stop->on;
    }
    return;
  }
  std::visit(
      [&](const auto& p) {
        using T = std::decay_t<decltype(p)>;
        if constexpr (requires { p.spindle; } && !std::is_same_v<T, act::SpindleCmd>) {
          plc::SpindleControl* sc = spindle_control(p.spindle);
          if (!sc) return;
          if constexpr (std::is_same_v<T, act::SpindleOverride>) sc->override_percent = p.percent, sc->override_valid = true;
          else if constexpr (std::is_same_v<T, act::OverrideValid>) sc->override_valid = p.on;
          else if constexpr (std::is_same_v<T, act::SpindleFeedhold>) sc->feedhold = p.on;
          else if constexpr (std::is_same_v<T, act::SpindleStopAtEnd>) sc->stop_at_program_end = p.on;
          else if constexpr (std::is_same_v<T, act::SpindleReset>) sc->reset = true;
        }
      },
      a.payload);
}

}  // namespace nck::sim
