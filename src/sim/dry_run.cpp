#include "nck/sim/dry_run.hpp"

#include <fmt/format.h>

#include "nck/prep/planner.hpp"

namespace nck::sim {

// The texts that name the axis a 930740 refusal concerns, for the axes
// that require homing (P-AXIS-00277).
void DryRun::name_unhomed_axes(DryRun& run, std::size_t ch) {
  const config::ChannelConfig& c = run.machine_->channels[ch];
  for (std::size_t j = 0; j < c.axes.size() && j < kMaxAxes; ++j) {
    const int a = c.axes[j].axis_index;
    if (a < 0 || !run.machine_->axes[static_cast<std::size_t>(a)].prog_move_requires_homing) continue;
    const std::uint32_t m = run.store_->add_message(fmt::format(
        "axis {} is not homed and its machine data require homing before a programmed motion "
        "(kenngr.prog_move_requires_homing, P-AXIS-00277): home it with G74 (or Home in the HMI) first",
        c.axes[j].name));
    run.kernel_->name_unhomed_axis(ch, j, m);
  }
}

std::expected<DryRun, Diagnostic> DryRun::create(const config::Machine& m,
                                                 const std::vector<std::filesystem::path>& programs,
                                                 const DryRunOptions& options) {
  DryRun run;
  run.machine_ = std::make_unique<const config::Machine>(m);
  run.kernel_ = std::make_unique<kernel::Kernel>();
  if (auto ok = run.kernel_->configure(*run.machine_); !ok) return std::unexpected(ok.error());
  run.sim_ = std::make_unique<MachineSim>(*run.machine_);
  run.kernel_->attach_drives(&run.sim_->drives());
  run.store_ = std::make_unique<prep::PlanStore>();
  run.in_ = std::make_unique<kernel::TickInput>();
  run.threaded_ = options.prep_thread;
  for (std::size_t ch = 0; ch < run.machine_->channels.size(); ++ch) {
    const bool has_program = ch < programs.size();
    prep::PrepOptions prep{options.clamp_index, options.record_frames, options.stop, std::nullopt,
                           options.allowed_roots, options.record_modal};
    if (ch == options.search_channel && has_program) prep.search = options.search;
    run.preps_.emplace_back(*run.machine_, ch, has_program ? programs[ch] : std::filesystem::path(), *run.store_,
                            prep);
    run.queues_.push_back({&run.kernel_->commands(ch), &run.kernel_->feedback(ch)});
  }
  for (std::size_t ch = 0; ch < run.preps_.size() && ch < config::kMaxChannels; ++ch) {
    if (const auto& at = options.start_mcs[ch]) {
      run.kernel_->start_channel_at(ch, *at);
      run.preps_[ch].start_at(*at);
    }
    if (const auto& homed = options.homed_axes[ch]) run.kernel_->set_homed_axes(ch, *homed);
    name_unhomed_axes(run, ch);
    run.sim_->start_with_skip_mask(ch, options.skip_masks[ch]);
    if (options.skip_masks[ch] != 0) run.preps_[ch].set_skip_mask(options.skip_masks[ch]);
  }
  return run;
}

void DryRun::carry_homing(const DryRun& before) noexcept {
  const std::size_t n = std::min(kernel_->channel_count(), before.kernel_->channel_count());
  for (std::size_t ch = 0; ch < n; ++ch) kernel_->set_homed_axes(ch, before.kernel_->homed_axes(ch));
}

DryRun::~DryRun() { stop_preparation(); }
DryRun::DryRun(DryRun&&) noexcept = default;
DryRun& DryRun::operator=(DryRun&&) noexcept = default;

// With a preparation thread the cycles run on while every queue holds this
// many commands: enough for any braking the look-ahead plans within its
// depth, so the kernel's reserve never binds where one thread's would not.
constexpr std::size_t kQueuedAhead = kernel::kMaxLookAheadDepth;

void DryRun::prepare_now() {
  take_resets();
  if (!sim_->mdi_requests().empty()) submit_mdi();
  if (threaded_) {
    feed_preparation_thread();
    prep_thread_->wait_caught_up(kQueuedAhead);
    prep_thread_->rethrow_failure();
    switch_sensors_on();
    return;
  }
  for (std::size_t ch = 0; ch < preps_.size(); ++ch) {
    if (sim_->skip_levels_used()) preps_[ch].set_skip_mask(sim_->hli().channel[ch].skip_mask);
    // Preparation runs ahead of the kernel: the sensor is on before the
    // kernel takes the first #DIST CTRL ON (planned by a call that progressed).
    const ChannelQueues& q = queues_[ch];
    const bool channel_done = kernel_->channel_done(ch);
    const bool progressed = preps_[ch].feed(*q.commands, *q.feedback, channel_done);
    if (progressed && preps_[ch].planner().technologies().get<prep::DistUnit>().programmed())
      sim_->switch_sensor_on(ch);
  }
}

void DryRun::start_preparation_thread() {
  if (prep_thread_) return;
  std::array<std::uint32_t, config::kMaxChannels> masks{};
  for (std::size_t ch = 0; ch < preps_.size() && ch < masks.size(); ++ch) masks[ch] = sim_->hli().channel[ch].skip_mask;
  prep_thread_ = std::make_unique<PrepThread>(preps_, *kernel_, masks);
}

void DryRun::prepare_live() {
  if (!prep_thread_) return;
  take_resets();
  if (!sim_->mdi_requests().empty()) submit_mdi();
  feed_preparation_thread();
  prep_thread_->rethrow_failure();
  switch_sensors_on();
}

// What the cycle side hands the preparation thread before a cycle.
void DryRun::feed_preparation_thread() {
  start_preparation_thread();  // here, once this object has stopped moving
  if (sim_->skip_levels_used())
    for (std::size_t ch = 0; ch < preps_.size(); ++ch) prep_thread_->set_skip_mask(ch, sim_->hli().channel[ch].skip_mask);
}

// The distance sensors of the channels whose preparation has met #DIST CTRL ON.
void DryRun::switch_sensors_on() {
  for (std::size_t ch = 0; ch < preps_.size(); ++ch)
    if (prep_thread_->sensor_wanted(ch)) sim_->switch_sensor_on(ch);
}

void DryRun::cycle(kernel::TickOutput& out) noexcept {
  sim_->read(kernel_->time_s(), *in_);
  kernel_->tick(*in_, out);
  for (std::size_t ch = 0; ch < preps_.size() && ch < reset_seen_.size(); ++ch)
    reset_seen_[ch] = reset_seen_[ch] || in_->channels[ch].reset;
  sim_->write(out);
  if (prep_thread_) prep_thread_->cycle_done();
}

void DryRun::stop_preparation() {
  if (prep_thread_) prep_thread_->stop();
}

bool DryRun::done() const noexcept {
  for (std::size_t ch = 0; ch < preps_.size(); ++ch)
    if (preps_[ch].has_program() && !kernel_->channel_done(ch)) return false;
  // An ended channel may still be jogged: the run goes on until that is over.
  for (std::size_t ch = 0; ch < preps_.size(); ++ch)
    if (kernel_->channel_jogging(ch)) return false;
  if (sim_->jog_pending()) return false;
  if (!sim_->runs_mdi()) return true;
  // Between two MDI texts the channel is done while the next one's
  // commands wait in its queue: they run before the run ends.
  for (std::size_t ch = 0; ch < preps_.size(); ++ch)
    if (preps_[ch].mdi_used() &&
        (preps_[ch].mdi_pending() || !kernel_->channel_done(ch) || !kernel_->commands(ch).empty()))
      return false;
  return !sim_->scenario_pending() && sim_->mdi_requests().empty();
}

void DryRun::take_resets() {
  for (std::size_t ch = 0; ch < preps_.size() && ch < reset_seen_.size(); ++ch) {
    if (!reset_seen_[ch]) continue;
    reset_seen_[ch] = false;
    braking_[ch] = !kernel_->channel_done(ch);
    if (const std::size_t n = preps_[ch].discard_mdi(); n > 0)
      refusals_.push_back(Refusal{static_cast<std::uint8_t>(ch + 1),
                                  make_diagnostic(ErrorId::KernelMdiDiscarded, SourceLoc{"operator", 1, 0},
                                                  fmt::format("a reset of channel {} discarded {} MDI text(s) "
                                                              "typed before it that had not run",
                                                              ch + 1, n))});
  }
}

void DryRun::submit_mdi() {
  for (const MachineSim::MdiRequest& r : sim_->mdi_requests()) {
    if (r.channel < 1 || r.channel > preps_.size()) continue;
    const std::size_t ch = r.channel - 1u;
    auto refused = mdi(ch, sim_->mdi_text(r.text), kernel_->program_state(ch), SourceLoc{sim_->scenario_file(), r.line, 0});
    if (refused) refusals_.push_back(Refusal{r.channel, std::move(*refused)});
  }
  sim_->mdi_requests().clear();
}

// MDI is for an idle channel: before its program, after its end or a reset,
// or while it runs the MDI text before (the texts queue up).
std::optional<Diagnostic> DryRun::mdi(std::size_t ch, const std::string& text, kernel::ProgramState st,
                                      const SourceLoc& loc, bool queue) {
  auto refused = [&](std::string_view why) {
    return make_diagnostic(ErrorId::KernelMdiRefused, loc, fmt::format("MDI '{}' refused: channel {} {}", text, ch + 1, why));
  };
  // E-stop, machine off or an amplifier fault: refused with their IDs (the kernel would drop it).
  const kernel::MachineOutput& machine = kernel_->machine_state();
  if (machine.estop || kernel_->estop_latched(ch))
    return make_diagnostic(ErrorId::KernelEstopRefused, loc, fmt::format("MDI '{}' refused: the E-stop is active or not reset", text));
  if (!machine.machine_on)
    return make_diagnostic(ErrorId::KernelMachineOffRefused, loc, fmt::format("MDI '{}' refused: the machine is off", text));
  if (kernel_->amp_fault_latched(ch))
    return make_diagnostic(ErrorId::KernelAmpFaultRefused, loc,
                           fmt::format("MDI '{}' refused: an amplifier fault is on or not reset", text));
  braking_[ch] = braking_[ch] && !kernel_->channel_done(ch);
  if (braking_[ch]) return refused("brakes after a reset");
  const bool idle = st == kernel::ProgramState::idle || st == kernel::ProgramState::ended;
  // MDI was only ever taken once the program was over: running now is MDI.
  const bool in_mdi = preps_[ch].mdi_pending() || (preps_[ch].mdi_used() && st == kernel::ProgramState::running);
  if (!idle && !in_mdi) return refused(fmt::format("is {}", kernel::state_name(st)));
  if (in_mdi && !queue) return refused("runs an MDI text; ask to queue it (\"queue\": true) to run it after that one");
  preps_[ch].submit_mdi(text);
  if (prep_thread_) prep_thread_->wake();
  return std::nullopt;
}

void DryRun::offer_zero_offsets(std::size_t ch, const config::ZeroOffsets& zero) {
  if (ch >= preps_.size()) return;
  preps_[ch].offer_zero_offsets(zero);
  if (prep_thread_) prep_thread_->wake();
}

std::optional<Diagnostic> DryRun::operate(const OperatorAction& op) {
  const SourceLoc loc{"operator", 1, 0};
  if (op.action.kind() == ActionKind::mdi) {
    if (op.action.channel < 1 || op.action.channel > preps_.size())
      return make_diagnostic(ErrorId::PlcOperatorActionBad, loc, fmt::format("no channel {}", op.action.channel));
    const std::size_t ch = op.action.channel - 1u;
    return mdi(ch, op.mdi_text, kernel_->program_state(ch), loc);
  }
  if (sim_->operate(op.action)) return std::nullopt;
  return make_diagnostic(ErrorId::PlcOperatorActionsFull, loc,
                         fmt::format("'{}' dropped: 32 actions already wait for the next cycle", action_name(op.action.kind())));
}

bool DryRun::held_for_good() const noexcept {
  bool any = false;
  for (std::size_t ch = 0; ch < preps_.size(); ++ch) {
    if (!preps_[ch].has_program()) continue;
    // Most cycles a channel runs: one question answers it.
    const kernel::ProgramState state = kernel_->program_state(ch);
    if (state != kernel::ProgramState::hold) {
      if (kernel_->channel_done(ch)) continue;
      // Manual mode keeps a program from starting as a hold does.
      if (state != kernel::ProgramState::idle || !sim_->manual_mode(ch)) return false;
    }
    if (sim_->auto_cycle_start(ch) && !sim_->manual_mode(ch)) return false;
    if (kernel_->channel_jogging(ch)) return false;
    any = true;
  }
  return any && !sim_->scenario_pending();
}

ChannelSnapshot DryRun::snapshot(std::size_t ch) const {
  const kernel::ChannelState state = kernel_->channel_state(ch);
  const prep::Planner& planner = preps_.at(ch).planner();
  const prep::ChannelFrames& f = planner.frames();
  const motion::AxisVector pcs = f.to_pcs(planner.cartesian(state.path_mcs));
  ChannelSnapshot s;
  std::vector<std::pair<std::string, double>> manual;
  bool any_manual = false;
  for (std::size_t j = 0; j < planner.axis_count(); ++j) {
    s.axis_mcs[j] = state.axis_mcs[j];
    s.axis_pcs[j] = pcs[j];
    manual.emplace_back(f.axis_name(j), state.manual_offsets[j]);
    any_manual = any_manual || state.manual_offsets[j] != 0;
  }
  for (const frames::OffsetEntry& e : f.active())
    s.offsets.emplace_back(std::string(frames::to_string(e.kind)), f.values_of(e.kind, false));
  if (any_manual) s.offsets.emplace_back("manual", std::move(manual));
  s.modal = planner.modal();
  s.status = state.status;
  return s;
}

}  // namespace nck::sim
