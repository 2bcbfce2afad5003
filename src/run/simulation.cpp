#include "nck/run/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

#include <fmt/format.h>

#include "nck/run/path_track.hpp"
#include "nck/run/stop_request.hpp"

namespace nck::app {
namespace {

Diagnostic usage(std::string text) { return make_diagnostic(ErrorId::AppBadUsage, {}, std::move(text)); }

// A scenario's text, parsed and resolved; errors make it unusable,
// warnings go to the console.
std::expected<sim::Scenario, Diagnostics> scenario_of(std::string_view text, const std::string& file,
                                                      const config::Machine& m, Console& console) {
  Diagnostics ds;
  sim::Scenario sc = sim::parse_scenario(text, file, ds);
  sim::resolve_spindles(sc, m, plc::build_spindle_map(m), ds);
  if (ds.has_errors()) return std::unexpected(ds);
  for (const Diagnostic& d : ds.items()) console.line(format(d));
  return sc;
}

// The --plc scenario file.
std::expected<sim::Scenario, Diagnostics> load_scenario(const std::string& path, const config::Machine& m,
                                                        Console& console) {
  std::error_code ec;
  std::ifstream f(path, std::ios::binary);
  if (!std::filesystem::is_regular_file(path, ec) || !f) {
    Diagnostics ds;
    ds.add(ErrorId::AppScenarioUnreadable, SourceLoc{path, 0, 0}, "cannot read the PLC scenario");
    return std::unexpected(ds);
  }
  std::stringstream text;
  text << f.rdbuf();
  return scenario_of(text.str(), path, m, console);
}

// `from`'s lines after `into`'s at equal times (both are sorted by time);
// one block search in all. false (the reason in ds) when both search.
bool append_scenario(sim::Scenario& into, sim::Scenario from, Diagnostics& ds) {
  if (sim::block_search_of(from) && sim::block_search_of(into)) {
    for (const sim::ScenarioAction& a : from.actions)
      if (a.kind() == sim::ActionKind::block_search)
        ds.add(ErrorId::PlcScenarioBlockSearch, SourceLoc{from.file, a.line, 1},
               fmt::format("a second block_search line (after {}'s); a run has one block search", into.file));
    return false;
  }
  const auto base = static_cast<std::uint32_t>(into.texts.size());
  for (std::vector<sim::ScenarioAction>* list : {&from.actions, &from.triggered})
    for (sim::ScenarioAction& a : *list)
      if (auto* mdi = a.get<sim::act::Mdi>()) mdi->text += base;  // its text's index among all texts
  std::ranges::move(from.texts, std::back_inserter(into.texts));
  std::ranges::move(from.triggered, std::back_inserter(into.triggered));
  const auto middle = static_cast<std::ptrdiff_t>(into.actions.size());
  std::ranges::move(from.actions, std::back_inserter(into.actions));
  std::inplace_merge(into.actions.begin(), into.actions.begin() + middle, into.actions.end(),
                     [](const sim::ScenarioAction& x, const sim::ScenarioAction& y) { return x.t_s < y.t_s; });
  into.file = into.file.empty() ? from.file : into.file;
  return true;
}

// The run's scenario: the embedding's texts (RunOptions::plc_texts), then
// the --plc file, merged by time.
std::expected<sim::Scenario, Diagnostics> run_scenario(const RunOptions& opt, const config::Machine& m,
                                                       Console& console) {
  sim::Scenario all;
  Diagnostics ds;
  for (const RunOptions::PlcText& t : opt.plc_texts) {
    auto sc = scenario_of(t.text, t.name, m, console);
    if (!sc) return sc;
    if (!append_scenario(all, std::move(*sc), ds)) return std::unexpected(ds);
  }
  if (!opt.plc.empty()) {
    auto sc = load_scenario(opt.plc, m, console);
    if (!sc) return sc;
    if (!append_scenario(all, std::move(*sc), ds)) return std::unexpected(ds);
  }
  return all;
}

// The run's block search: --start-at & co. (channel 1) or the scenario's
// block_search line, never both.
std::expected<std::optional<sim::ScenarioSearch>, Diagnostic> block_search_of(const RunOptions& opt,
                                                                             const sim::Scenario& sc) {
  std::optional<sim::ScenarioSearch> s = sim::block_search_of(sc);
  if (s && opt.start_at)
    return std::unexpected(usage("--start-at and the --plc scenario's block_search line both ask for a block search; give one"));
  if (opt.covered_pct && !opt.start_at)
    return std::unexpected(usage("--covered belongs to a block search: give --start-at, --start-at-block or --start-at-offset"));
  if (opt.start_at) {
    s = sim::ScenarioSearch{0, *opt.start_at};
    if (opt.covered_pct) s->mark.covered_permille = *opt.covered_pct * 10.0;
  }
  if (config::canonical_start_mode(opt.start_mode) == "SV" && !s)
    return std::unexpected(usage("--start-mode SV belongs to a block search: give --start-at, --start-at-block or --start-at-offset"));
  return s;
}

kernel::StateReason state_reason_of(kernel::EndReason r) {
  using R = kernel::EndReason;
  switch (r) {
    case R::max_time: return kernel::StateReason::max_time;
    case R::max_wall: return kernel::StateReason::max_wall;
    case R::interrupted: return kernel::StateReason::interrupted;
    case R::hold: return kernel::StateReason::hold;
    case R::stop_at: return kernel::StateReason::stop_at;
    case R::max_trace: return kernel::StateReason::max_trace;
    case R::max_events: return kernel::StateReason::max_events;
    default: return kernel::StateReason::error;
  }
}

bool any_channel_aborted(const sim::DryRun& run) {
  for (std::size_t ch = 0; ch < run.kernel().channel_count(); ++ch)
    if (run.kernel().channel_state(ch).status == kernel::ChannelStatus::aborted) return true;
  return false;
}

// A channel an error ended (and no reset cleared since): a reset alone is
// an operator's action, not a failure.
bool any_channel_failed(const sim::DryRun& run) {
  for (std::size_t ch = 0; ch < run.kernel().channel_count(); ++ch)
    if (run.kernel().channel_state(ch).program_state == kernel::ProgramState::error) return true;
  return false;
}

Diagnostics one(Diagnostic d) {
  Diagnostics ds;
  ds.add(std::move(d));
  return ds;
}

}  // namespace

std::string cli_text(const Diagnostic& d) {
  if (!d.loc.file.empty() || d.id != ErrorId::AppBadUsage) return format(d);
  return fmt::format("nck: {} {}: {}", d.severity == Severity::error ? "error" : "warning", number(d.id), d.message);
}

Simulation::Simulation(const RunOptions& opt, Host host)
    : opt_(opt),
      out_(host == Host::embedded),
      progress_(opt.progress && host == Host::cli, opt.programs),
      stop_(host == Host::cli ? &stop_flag() : &own_stop_) {}

Simulation::~Simulation() = default;

std::expected<std::unique_ptr<Simulation>, Diagnostics> Simulation::create(config::Machine m, const RunOptions& opt,
                                                                           Host host) {
  std::unique_ptr<Simulation> s(new Simulation(opt, host));
  for (const std::string& dir : opt.cycles) m.cycle_paths.emplace_back(dir);
  auto scenario = run_scenario(opt, m, s->out_.console);
  if (!scenario) return std::unexpected(scenario.error());
  s->scenario_ = std::make_unique<sim::Scenario>(std::move(*scenario));
  const auto search = block_search_of(opt, *s->scenario_);
  if (!search) return std::unexpected(one(search.error()));
  // A searched program runs in the block-search start mode (P-CHAN-00508 SV) throughout.
  const std::string start_mode = !opt.start_mode.empty() ? opt.start_mode : *search ? "SV" : "ISG_STANDARD";
  for (config::ChannelConfig& c : m.channels) c.start_mode = start_mode;
  // Without a program the channels wait for the scenario's MDI lines.
  if ((opt.programs.empty() && s->scenario_->texts.empty() && !opt.operator_present) ||
      opt.programs.size() > m.channels.size())
    return std::unexpected(one(usage(fmt::format(
        "{} program(s) given for {} channel(s); give one per channel (or none, with a --plc scenario that "
        "types mdi lines)",
        opt.programs.size(), m.channels.size()))));
  s->machine_ = std::make_unique<config::Machine>(std::move(m));
  sim::DryRunOptions options;
  options.clamp_index = opt.clamp_index;
  options.record_frames = !opt.report.empty() || opt.operator_present;
  // a session's state gives the modal state of the block in execution (RunOutputs::blocks);
  // a report's player shows a diameter under G51 where the machine says so
  // (P-CHAN-00256): only then, as each modal change costs a map entry
  const bool diameter_dro = std::ranges::any_of(s->machine_->channels, [](const auto& c) { return c.display_diameter_pos; });
  options.record_modal = opt.operator_present || (!opt.report.empty() && diameter_dro);
  options.prep_thread = opt.prep_thread;
  if (opt.unhomed) options.homed_axes.fill(0u);  // without it the operator homed the machine
  options.stop = s->stop_;
  if (*search) {
    options.search = (*search)->mark;
    options.search_channel = (*search)->channel;
  }
  const std::vector<std::filesystem::path> programs(opt.programs.begin(), opt.programs.end());
  auto created = sim::DryRun::create(*s->machine_, programs, options);
  if (!created) return std::unexpected(one(created.error()));
  s->run_ = std::make_unique<sim::DryRun>(std::move(*created));
  if (!opt.plc.empty() || !opt.plc_texts.empty()) s->run_->load_scenario(*s->scenario_);
  s->names_.run = s->run_.get();
  s->tick_ = std::make_unique<kernel::TickOutput>();
  if (opt.stop_at) s->stop_at_.emplace(*opt.stop_at, *s->run_);
  // the ledger per line, tool and file only for an output that shows it
  const bool by_line = host == Host::embedded || !opt.final_state.empty() || !opt.report.empty();
  s->out_.causes.start(*s->machine_, s->run_->kernel().cycle_time_s(), by_line);
  if (opt.track) opt.track->start(*s->machine_);
  return s;
}

// A cycle whose events did not all fit its output: never lost silently.
void Simulation::report_dropped_events(const kernel::TickOutput& o) {
  if (o.events_dropped == 0) return;
  progress_.clear();
  const kernel::Event e{{o.t_s, 0, {}}, kernel::ev::Warning{{ErrorId::KernelEventsDropped, {}, {}}}};
  const std::string text = fmt::format("{} event(s) of the cycle at {} s were not recorded", o.events_dropped, o.t_s);
  out_.console.line(fmt::format("nck: warning {}: {}", number(ErrorId::KernelEventsDropped), text));
  out_.warnings.push_back(FinalError{number(ErrorId::KernelEventsDropped), 0, 0, std::string(), text});
  if (out_.wants_events()) out_.event(e, names_);
}

// Operator actions the channel could not take (an MDI line while a program
// runs): a warning with its ID, on stderr and as an event.
void Simulation::report_refusals(const kernel::TickOutput& o) {
  for (const auto& [channel, d] : run_->take_refusals()) {
    progress_.clear();
    out_.console.line(format(d));
    out_.summary.warning();
    out_.warnings.push_back(FinalError{number(d.id), channel, d.loc.line, d.loc.file, d.message});
    if (!out_.wants_events()) continue;
    const kernel::Event e{{o.t_s, channel, {}}, kernel::ev::Warning{{d.id, {}, {}}}};
    out_.event(e, names_);
  }
}

void Simulation::record_events(const kernel::TickOutput& o) {
  progress_.take(o);
  for (const kernel::Event& e : o.events) {
    out_.summary.take(e);
    out_.last_errors.take(e, names_);
    note_event(out_.blocks, e, *run_);
    if (out_.wants_events()) {
      if (e.kind() == kernel::EventKind::block) out_.event_line(e, block_text_.line(e, names_), names_);
      else out_.event(e, names_);
    }
    const auto* error = e.get<kernel::ev::Error>();
    const auto* warning = e.get<kernel::ev::Warning>();
    if (!error && !warning) continue;
    const kernel::ev::Diagnosis& d = error ? static_cast<const kernel::ev::Diagnosis&>(*error) : *warning;
    // warnings too: every diagnostic reaches stderr, not only the events file
    const std::string file = e.channel > 0 ? names_.file(e.channel_index(), e.at.file_id) : std::string();
    progress_.clear();
    const FinalError said{number(d.id), e.channel, e.at.line, file, names_.text(d.id, d.message)};
    out_.console.line(format(Diagnostic{d.id, error ? Severity::error : Severity::warning,
                                        SourceLoc{file, e.at.line, 0}, said.msg}));
    (error ? out_.errors : out_.warnings).push_back(said);
  }
}

void Simulation::cycle() {
  kernel::TickOutput& o = *tick_;
  run_->prepare();
  run_->cycle(o);
  const std::uint64_t index = run_->kernel().cycles() - 1;
  out_.causes.take(o, names_);
  if (opt_.track) opt_.track->take(o);
  record_events(o);
  report_dropped_events(o);
  // tested here: most cycles have neither (nor their code in the cache)
  if (run_->has_refusals()) report_refusals(o);
  if (out_.trace.is_open()) out_.trace.write(index, o);
  if (!out_.trace_memory.write(index, o)) trace_full_ = true;
  out_.report.sample(index, o, names_, run_->machine().hli());
  if (stop_at_ && stop_at_->reached(o)) stop_at_reached_ = true;
  if (out_.event_memory.take_dropped() > 0) report_events_dropped(o);
}

// A session's events reached their bound and the oldest went: a warning
// event says so where they went missing. Only the event, no stderr line or
// warnings entry: those lists would grow with every drop.
void Simulation::report_events_dropped(const kernel::TickOutput& o) {
  const kernel::Event e{{o.t_s, 0, {}}, kernel::ev::Warning{{ErrorId::AppEventsDropped, {}, {}}}};
  out_.event(e, names_);
}

std::optional<kernel::EndReason> Simulation::run_to_end() {
  const auto wall_start = std::chrono::steady_clock::now();
  const WallClockLimit wall(opt_.max_wall_s, own_stop_flag());  // raises the stop flag, also inside a long decode
  for (;;) {
    const double t_s = run_->time_s();
    cycle();
    if (trace_full_) return kernel::EndReason::max_trace;
    if (out_.event_memory.full()) return kernel::EndReason::max_events;
    if (stop_at_reached_) return kernel::EndReason::stop_at;
    if (run_->done()) return std::nullopt;
    if (stop_->load(std::memory_order_relaxed))
      return stop_signal() != 0 && !own_stop_flag() ? kernel::EndReason::interrupted : kernel::EndReason::max_wall;
    if (run_->held_for_good()) return kernel::EndReason::hold;
    if (t_s + run_->kernel().cycle_time_s() >= opt_.max_time_s) return kernel::EndReason::max_time;
    if (opt_.realtime) std::this_thread::sleep_until(wall_start + std::chrono::duration<double>(t_s));
    progress_.update(t_s);
  }
}

// Every channel still running ends with the loop's reason; stderr says why.
void Simulation::end_unfinished_channels(kernel::EndReason reason) {
  const kernel::Kernel& k = run_->kernel();
  for (std::size_t ch = 0; ch < k.channel_count(); ++ch) {
    const kernel::ChannelState st = k.channel_state(ch);
    if (st.status == kernel::ChannelStatus::ended || st.status == kernel::ChannelStatus::aborted) continue;
    const EventHead head{run_->time_s(), static_cast<std::uint8_t>(ch + 1), st.at};
    const kernel::ev::State state{st.program_state, kernel::ProgramState::ended, state_reason_of(reason)};
    out_.event(kernel::Event{head, state}, names_);
    out_.event(kernel::Event{head, kernel::ev::End{reason}}, names_);
  }
  using R = kernel::EndReason;
  if (reason == R::max_time)
    out_.console.line(fmt::format("nck: the simulated-time limit of {} s was reached before the program end", opt_.max_time_s));
  else if (reason == R::max_wall)
    out_.console.line(fmt::format("nck: error {}: the wall-clock limit of {} s was reached before the program end",
                                  number(ErrorId::AppWallTimeLimit), opt_.max_wall_s));
  else if (reason == R::hold)
    out_.console.line(fmt::format(
        "nck: error {}: the program holds (M0/M1) and nothing releases it: the --plc scenario "
        "switched auto_cycle_start off and has no cycle_start line left, or left the channel in "
        "mode manual",
        number(ErrorId::AppHeldForGood)));
  else if (reason == R::interrupted)
    out_.console.line(fmt::format("nck: interrupted at {} s (simulated); the output files are complete", run_->time_s()));
  else if (reason == R::max_trace)
    report_memory_full(ErrorId::AppTraceMemoryLimit, "trace", out_.trace_memory.max_bytes());
  else if (reason == R::max_events)
    report_memory_full(ErrorId::AppEventMemoryLimit, "events", out_.event_memory.max_bytes());
}

// The memory limit of the trace or the events kept in memory ended the run: an error with its ID.
void Simulation::report_memory_full(ErrorId id, const char* what, std::uint64_t max_bytes) {
  const std::string text = fmt::format("the {} kept in memory reached the limit of {} bytes at {} s; the run ended there",
                                       what, max_bytes, run_->time_s());
  out_.console.line(fmt::format("nck: error {}: {}", number(id), text));
  out_.errors.push_back(FinalError{number(id), 0, 0, std::string(), text});
}

void Simulation::finish(std::optional<kernel::EndReason> stopped) {
  stopped_ = stopped;
  out_.event_memory.lift_bound();  // the closing state and end events of a run that hit it
  progress_.clear();
  run_->stop_preparation();  // what is read below belongs to preparation
  if (stopped) end_unfinished_channels(*stopped);
  out_.causes.finish();
}

int Simulation::exit_code() const {
  int code = 0;
  if (stopped_ == kernel::EndReason::interrupted) code = signal_exit_code();
  else if (stopped_ == kernel::EndReason::stop_at) code = any_channel_failed(*run_) ? 1 : 0;  // as asked for
  else code = stopped_ || any_channel_failed(*run_) ? 1 : 0;
  if (code == 0 && !out_.errors.empty()) code = 1;  // an MDI error ends no channel, but the run found one
  return code;
}

std::string Simulation::end_reason() const {
  if (stopped_) return end_name(*stopped_);
  if (!any_channel_aborted(*run_)) return "program_end";
  return out_.summary.reset_seen() ? "reset" : "error";
}

nlohmann::json Simulation::final_json() const {
  return app::final_json(*machine_, *run_, run_->time_s(), end_reason(), out_.errors, out_.causes.json());
}

}  // namespace nck::app
