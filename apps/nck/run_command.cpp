// `nck run`: load the machine, decode each channel's program, tick the
// kernel until every channel ends (or a limit or a signal stops the run), and
// write events, trace, report and final state, always complete.
#include "run_command.hpp"

#include <chrono>
#include <filesystem>
#include <memory>
#include <fstream>
#include <optional>
#include <sstream>
#include <cstdio>
#include <fmt/format.h>
#include <thread>
#include <unistd.h>

#include "nck/config/load.hpp"
#include "nck/sim/scenario.hpp"
#include "nck/sim/dry_run.hpp"
#include "output_writers.hpp"
#include "path_track.hpp"
#include "progress.hpp"
#include "run_outputs.hpp"
#include "stop_request.hpp"

namespace nck::app {
namespace {

bool print_load_diagnostics(const config::LoadResult& r) {
  for (const Diagnostic& d : r.diagnostics.items()) fmt::print(stderr, "{}\n", format(d));
  return r.ok();
}

// A cycle whose events did not all fit its output: never lost silently.
void report_dropped_events(const kernel::TickOutput& o, const RunNames& names, RunOutputs& out, Progress& progress) {
  if (o.events_dropped == 0) return;
  progress.clear();
  kernel::Event e;
  e.t_s = o.t_s;
  e.kind = kernel::EventKind::warning;
  e.id = ErrorId::KernelEventsDropped;
  e.message_index = kernel::kNoMessage;
  e.value = o.events_dropped;
  fmt::print(stderr, "nck: warning {}: {} event(s) of the cycle at {} s were not recorded\n",
             number(e.id), o.events_dropped, o.t_s);
  if (out.wants_events()) out.event(EventWriter::line(e, names), false);
}

// Operator actions the channel could not take (an MDI line while a program
// runs): a warning with its ID, on stderr and as an event.
void report_refusals(sim::DryRun& run, const kernel::TickOutput& o, const RunNames& names, RunOutputs& out,
                     Progress& progress) {
  for (const auto& [channel, d] : run.take_refusals()) {
    progress.clear();
    fmt::print(stderr, "{}\n", format(d));
    out.summary.warning();
    if (!out.wants_events()) continue;
    kernel::Event e;
    e.t_s = o.t_s;
    e.channel = channel;
    e.kind = kernel::EventKind::warning;
    e.id = d.id;
    e.message_index = kernel::kNoMessage;
    out.event(EventWriter::line(e, names), false);
  }
}

// A reset from the --plc scenario ends the program with exit 1: say so with an ID.
void report_reset(const kernel::Event& e, RunOutputs& out, Progress& progress) {
  const std::string text = fmt::format("the PLC scenario reset channel {} at {} s, before its program end",
                                       e.channel, e.t_s);
  progress.clear();
  fmt::print(stderr, "nck: error {}: {}\n", number(ErrorId::AppChannelReset), text);
  out.errors.push_back(FinalError{number(ErrorId::AppChannelReset), e.channel, 0, std::string(), text});
}

void record_events(const kernel::TickOutput& o, const RunNames& names, RunOutputs& out, Progress& progress) {
  progress.take(o);
  for (const kernel::Event& e : o.events) {
    out.summary.take(e);
    if (out.wants_events()) out.event(EventWriter::line(e, names), e.kind == kernel::EventKind::error);
    if (e.kind == kernel::EventKind::end && e.end_reason == kernel::EndReason::reset) report_reset(e, out, progress);
    const bool error = e.kind == kernel::EventKind::error;
    if (!error && e.kind != kernel::EventKind::warning) continue;
    const std::size_t ch = e.channel - 1u;
    // warnings too: every diagnostic reaches stderr, not only the events file
    const std::string file = e.channel > 0 ? names.file(ch, e.file_id) : std::string();
    progress.clear();
    fmt::print(stderr, "{}\n", format(Diagnostic{e.id, error ? Severity::error : Severity::warning,
                                                SourceLoc{file, e.line, 0}, names.text(e)}));
    if (error) out.errors.push_back(FinalError{number(e.id), e.channel, e.line, file, names.text(e)});
  }
}

// The --plc scenario; its diagnostics go to stderr, errors make it unusable.
std::optional<sim::Scenario> load_scenario(const std::string& path, const config::Machine& m) {
  std::error_code ec;
  std::ifstream f(path, std::ios::binary);
  if (!std::filesystem::is_regular_file(path, ec) || !f) {
    fmt::print(stderr, "{}: error 940003: cannot read the PLC scenario\n", path);
    return std::nullopt;
  }
  std::stringstream text;
  text << f.rdbuf();
  Diagnostics ds;
  sim::Scenario sc = sim::parse_scenario(text.str(), path, ds);
  sim::resolve_spindles(sc, m, plc::build_spindle_map(m), ds);
  for (const Diagnostic& d : ds.items()) fmt::print(stderr, "{}\n", format(d));
  if (ds.has_errors()) return std::nullopt;
  return sc;
}

// The run's block search: --start-at & co. (channel 1) or the scenario's
// block_search line, never both. `refused`: bad usage, said on stderr.
std::optional<sim::ScenarioSearch> block_search_of(const RunOptions& opt, const sim::Scenario& sc, bool& refused) {
  const auto refuse = [&](std::string_view why) -> std::optional<sim::ScenarioSearch> {
    fmt::print(stderr, "nck: error {}: {}\n", number(ErrorId::AppBadUsage), why);
    refused = true;
    return std::nullopt;
  };
  std::optional<sim::ScenarioSearch> s = sim::block_search_of(sc);
  if (s && opt.start_at) return refuse("--start-at and the --plc scenario's block_search line both ask for a block search; give one");
  if (opt.covered_pct && !opt.start_at)
    return refuse("--covered belongs to a block search: give --start-at, --start-at-block or --start-at-offset");
  if (opt.start_at) {
    s = sim::ScenarioSearch{0, *opt.start_at};
    if (opt.covered_pct) s->mark.covered_permille = *opt.covered_pct * 10.0;
  }
  if (config::canonical_start_mode(opt.start_mode) == "SV" && !s)
    return refuse("--start-mode SV belongs to a block search: give --start-at, --start-at-block or --start-at-offset");
  return s;
}

// Why the loop stopped before every channel ended, if it did.
std::optional<kernel::EndReason> run_loop(sim::DryRun& run, const RunOptions& opt, const RunNames& names,
                                          RunOutputs& out) {
  auto o = std::make_unique<kernel::TickOutput>();
  Progress progress(opt.progress, opt.programs);
  const auto wall_start = std::chrono::steady_clock::now();
  const WallClockLimit wall(opt.max_wall_s);  // raises stop_flag(), also inside a long decode
  std::optional<StopAtWatch> stop_at;
  if (opt.stop_at) stop_at.emplace(*opt.stop_at, run);
  for (;;) {
    const double t_s = run.time_s();
    run.prepare();
    run.cycle(*o);
    out.causes.take(*o, names);
    if (opt.track) opt.track->take(*o);
    record_events(*o, names, out, progress);
    report_dropped_events(*o, names, out, progress);
    report_refusals(run, *o, names, out, progress);
    out.trace.write(run.kernel().cycles() - 1, *o);
    out.report.sample(run.kernel().cycles() - 1, *o, names);
    if (stop_at && stop_at->reached(*o)) return kernel::EndReason::stop_at;
    if (run.done()) return std::nullopt;
    if (stop_flag().load(std::memory_order_relaxed))
      return stop_signal() != 0 ? kernel::EndReason::interrupted : kernel::EndReason::max_wall;
    if (run.held_for_good()) return kernel::EndReason::hold;
    if (t_s + run.kernel().cycle_time_s() >= opt.max_time_s) return kernel::EndReason::max_time;
    if (opt.realtime) std::this_thread::sleep_until(wall_start + std::chrono::duration<double>(t_s));
    progress.update(t_s);
  }
}

kernel::StateReason state_reason_of(kernel::EndReason r) {
  using R = kernel::EndReason;
  switch (r) {
    case R::max_time: return kernel::StateReason::max_time;
    case R::max_wall: return kernel::StateReason::max_wall;
    case R::interrupted: return kernel::StateReason::interrupted;
    case R::hold: return kernel::StateReason::hold;
    case R::stop_at: return kernel::StateReason::stop_at;
    default: return kernel::StateReason::error;
  }
}

// Every channel still running ends with the loop's reason; stderr says why.
void end_unfinished_channels(const sim::DryRun& run, kernel::EndReason reason, const RunOptions& opt,
                             const RunNames& names, RunOutputs& out) {
  const kernel::Kernel& k = run.kernel();
  for (std::size_t ch = 0; ch < k.channel_count(); ++ch) {
    const kernel::ChannelState st = k.channel_state(ch);
    if (st.status == kernel::ChannelStatus::ended || st.status == kernel::ChannelStatus::aborted) continue;
    kernel::Event e = st.at;
    e.t_s = run.time_s();
    e.state_from = st.program_state;
    e.state_to = kernel::ProgramState::ended;
    e.state_reason = state_reason_of(reason);
    out.event(EventWriter::line(e, names), false);
    e.kind = kernel::EventKind::end;
    e.end_reason = reason;
    out.event(EventWriter::line(e, names), false);
  }
  if (reason == kernel::EndReason::max_time)
    fmt::print(stderr, "nck: the simulated-time limit of {} s was reached before the program end\n", opt.max_time_s);
  else if (reason == kernel::EndReason::max_wall)
    fmt::print(stderr, "nck: error {}: the wall-clock limit of {} s was reached before the program end\n",
               number(ErrorId::AppWallTimeLimit), opt.max_wall_s);
  else if (reason == kernel::EndReason::hold)
    fmt::print(stderr,
               "nck: error {}: the program holds (M0/M1) and nothing releases it: the --plc scenario "
               "switched auto_cycle_start off and has no cycle_start line left, or left the channel in "
               "mode manual\n",
               number(ErrorId::AppHeldForGood));
  else if (reason == kernel::EndReason::interrupted)
    fmt::print(stderr, "nck: interrupted at {} s (simulated); the output files are complete\n", run.time_s());
}

bool any_channel_aborted(const sim::DryRun& run) {
  for (std::size_t ch = 0; ch < run.kernel().channel_count(); ++ch)
    if (run.kernel().channel_state(ch).status == kernel::ChannelStatus::aborted) return true;
  return false;
}

// SPEC 2.2: 0 program end, 1 NC error or a limit, 130/143 SIGINT/SIGTERM.
int exit_code_of(const sim::DryRun& run, std::optional<kernel::EndReason> stopped) {
  if (stopped == kernel::EndReason::interrupted) return signal_exit_code();
  if (stopped == kernel::EndReason::stop_at) return any_channel_aborted(run) ? 1 : 0;  // as asked for
  return stopped || any_channel_aborted(run) ? 1 : 0;
}

// The final state's "end": why the run ended.
std::string end_of_run(const sim::DryRun& run, std::optional<kernel::EndReason> stopped, const RunSummary& s) {
  if (stopped) return end_name(*stopped);
  if (!any_channel_aborted(run)) return "program_end";
  return s.reset_seen() ? "reset" : "error";
}

// Completes every output file; a file that cannot be written is error 940002
// and exit 2 (an interrupted run keeps 130/143).
int finish_outputs(const sim::DryRun& run, const RunOptions& opt, const config::Machine& m,
                   std::optional<kernel::EndReason> stopped, RunOutputs& out) {
  int code = exit_code_of(run, stopped);
  if (code == 0 && !out.errors.empty()) code = 1;  // an MDI error ends no channel, but the run found one
  const double end_s = run.time_s();
  std::vector<std::string> failures;
  // Only now are all the files known that the programs called.
  const OutputsOverInputs over = outputs_over_inputs(opt, run);
  if (over.events) out.events.discard();
  else if (auto e = out.events.commit()) failures.push_back(*e);
  if (over.trace) out.trace.discard();
  else if (auto e = out.trace.commit()) failures.push_back(*e);
  out.causes.finish();
  const bool want_causes = !opt.final_state.empty() || !opt.report.empty();
  const nlohmann::ordered_json causes = want_causes ? out.causes.json() : nlohmann::ordered_json::object();
  out.report.set_causes(causes);
  if (!over.report)
    if (auto e = out.report.write(opt.report, end_s, code)) failures.push_back(*e);
  if (!opt.final_state.empty() && !over.final_state)
    if (auto e = write_final(opt.final_state, m, run, end_s, end_of_run(run, stopped, out.summary), out.errors,
                                 causes))
      failures.push_back(*e);
  for (const std::string& f : failures) fmt::print(stderr, "nck: error {}: {}\n", number(ErrorId::AppOutputFile), f);
  for (const std::string& f : over.messages)
    fmt::print(stderr, "nck: error {}: {}\n", number(ErrorId::AppOutputPathConflict), f);
  // the top causes first: the summary stays the last line (scripts read it)
  for (const std::string& line : out.causes.top_lines()) fmt::print(stderr, "{}\n", line);
  fmt::print(stderr, "{}\n", out.summary.text(end_of_run(run, stopped, out.summary), end_s));
  if ((!failures.empty() || over.any()) && code != 130 && code != 143) code = 2;
  return code;
}

}  // namespace

int run_simulation(const RunOptions& opt) {
  if (auto conflict = output_path_conflict(opt)) {
    fmt::print(stderr, "nck: error {}: {}\n", number(ErrorId::AppOutputPathConflict), *conflict);
    return 2;
  }
  for (const std::string& p : opt.programs) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec)) {  // bad usage, not an NC error
      fmt::print(stderr, "nck: error {}: the program {} does not exist or is not a file\n",
                 number(ErrorId::AppBadUsage), p);
      return 2;
    }
  }
  config::LoadResult loaded = config::load_machine(opt.machine);
  if (!print_load_diagnostics(loaded)) return 2;
  for (const std::string& dir : opt.cycles) loaded.machine->cycle_paths.emplace_back(dir);
  sim::Scenario scenario;
  if (!opt.plc.empty()) {
    auto loaded_scenario = load_scenario(opt.plc, *loaded.machine);
    if (!loaded_scenario) return 2;
    scenario = std::move(*loaded_scenario);
  }
  bool refused = false;
  const std::optional<sim::ScenarioSearch> search = block_search_of(opt, scenario, refused);
  if (refused) return 2;
  // A searched program runs in the block-search start mode (P-CHAN-00508 SV) throughout.
  const std::string start_mode = !opt.start_mode.empty() ? opt.start_mode : search ? "SV" : "ISG_STANDARD";
  for (config::ChannelConfig& c : loaded.machine->channels) c.start_mode = start_mode;
  const config::Machine& m = *loaded.machine;
  // Without a program the channels wait for the scenario's MDI lines.
  if ((opt.programs.empty() && scenario.texts.empty()) || opt.programs.size() > m.channels.size()) {
    fmt::print(stderr, "nck: error 940001: {} program(s) given for {} channel(s); give one per channel "
               "(or none, with a --plc scenario that types mdi lines)\n",
               opt.programs.size(), m.channels.size());
    return 2;
  }
  std::vector<std::filesystem::path> programs(opt.programs.begin(), opt.programs.end());
  sim::DryRunOptions options;
  options.clamp_index = opt.clamp_index;
  options.record_frames = !opt.report.empty();
  options.prep_thread = opt.prep_thread;
  options.stop = &stop_flag();
  if (search) {
    options.search = search->mark;
    options.search_channel = search->channel;
  }
  auto created = sim::DryRun::create(m, programs, options);
  if (!created) {
    fmt::print(stderr, "{}\n", format(created.error()));
    return 2;
  }
  sim::DryRun& run = *created;
  if (!opt.plc.empty()) run.load_scenario(scenario);
  RunOutputs out;
  for (const Diagnostic& d : loaded.diagnostics.items())  // printed above; the summary counts them too
    if (d.severity == Severity::warning) out.summary.warning();
  std::optional<std::string> open_error;
  if (!opt.events.empty()) open_error = out.events.open(opt.events, opt.realtime);
  if (!open_error && !opt.trace.empty())
    open_error = out.trace.open(opt.trace, opt.realtime, m, opt.trace_every,
                                opt.trace_columns.empty() ? TraceColumns{}
                                                          : parse_trace_columns(opt.trace_columns).value_or(TraceColumns{}));
  if (open_error) {
    fmt::print(stderr, "nck: error {}: {}\n", number(ErrorId::AppOutputFile), *open_error);
    return 2;
  }
  out.report.start(m, opt, run);
  out.causes.start(m, run.kernel().cycle_time_s());
  if (opt.track) opt.track->start(m);
  if (opt.ghost) out.report.set_ghost(*opt.ghost);
  RunNames names;
  names.run = &run;

  const std::optional<kernel::EndReason> stopped = run_loop(run, opt, names, out);
  run.stop_preparation();  // what is read below belongs to preparation
  if (stopped) end_unfinished_channels(run, *stopped, opt, names, out);
  return finish_outputs(run, opt, m, stopped, out);
}

}  // namespace nck::app
