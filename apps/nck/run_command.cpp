// `nck run`: load the machine, decode each channel's program, tick the
// kernel until every channel ends, and write events, trace and final state.
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
#include "nck/plc/scenario.hpp"
#include "nck/sim/dry_run.hpp"
#include "output_writers.hpp"
#include "report_writer.hpp"

namespace nck::app {
namespace {

struct Outputs {
  EventWriter events;
  TraceWriter trace;
  ReportWriter report;
  std::vector<FinalError> errors;

  // Events are rendered only when a file wants them.
  bool wants_events() const { return events.is_open() || report.enabled(); }
  void event(const std::string& line, bool is_error) {
    events.write_line(line);
    report.event(line, is_error);
  }
};

bool print_load_diagnostics(const config::LoadResult& r) {
  for (const Diagnostic& d : r.diagnostics.items()) fmt::print(stderr, "{}\n", format(d));
  return r.ok();
}

// Decoder warnings appear when decoded; errors travel through the channel
// queue so they are raised when execution reaches them.
void report_new_warnings(const sim::DryRun& run, double t_s, Outputs& out) {
  for (std::size_t ch = 0; ch < run.channel_count(); ++ch)
    for (const Diagnostic& d : run.new_warnings(ch)) {
      fmt::print(stderr, "{}\n", format(d));
      if (out.wants_events()) out.event(EventWriter::line(t_s, ch, d), false);
    }
}

// A cycle whose events did not all fit its output: never lost silently.
void report_dropped_events(const kernel::TickOutput& o, const RunNames& names, Outputs& out) {
  if (o.events_dropped == 0) return;
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

void record_events(const kernel::TickOutput& o, const RunNames& names, Outputs& out) {
  for (const kernel::Event& e : o.events) {
    if (out.wants_events()) out.event(EventWriter::line(e, names), e.kind == kernel::EventKind::error);
    if (e.kind != kernel::EventKind::error) continue;
    const std::size_t ch = e.channel - 1u;
    FinalError fe{number(e.id), e.channel, e.line, names.file(ch, e.file_id), names.text(e)};
    fmt::print(stderr, "{}:{}: error {}: {}\n", fe.file, fe.line, fe.id, fe.msg);
    out.errors.push_back(std::move(fe));
  }
}

class Progress {
 public:
  explicit Progress(bool enabled) : enabled_(enabled && isatty(fileno(stderr))) {}
  void update(double t_s) {
    if (!enabled_) return;
    auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    fmt::print(stderr, "\rnck: simulated {:.1f} s", t_s);
    shown_ = true;
  }
  ~Progress() {
    if (shown_) fmt::print(stderr, "\r\033[K");
  }

 private:
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point last_{};
};

// The --plc scenario; its diagnostics go to stderr, errors make it unusable.
std::optional<plc::Scenario> load_scenario(const std::string& path, const config::Machine& m) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    fmt::print(stderr, "{}: error 940003: cannot read the PLC scenario\n", path);
    return std::nullopt;
  }
  std::stringstream text;
  text << f.rdbuf();
  Diagnostics ds;
  plc::Scenario sc = plc::parse_scenario(text.str(), path, ds);
  plc::resolve_spindles(sc, m, plc::build_spindle_map(m), ds);
  for (const Diagnostic& d : ds.items()) fmt::print(stderr, "{}\n", format(d));
  if (ds.has_errors()) return std::nullopt;
  return sc;
}

}  // namespace

int run_simulation(const RunOptions& opt) {
  config::LoadResult loaded = config::load_machine(opt.machine);
  if (!print_load_diagnostics(loaded)) return 2;
  const config::Machine& m = *loaded.machine;
  if (opt.programs.empty() || opt.programs.size() > m.channels.size()) {
    fmt::print(stderr, "nck: error 940001: {} program(s) given for {} channel(s); give one per channel\n",
               opt.programs.size(), m.channels.size());
    return 2;
  }
  std::vector<std::filesystem::path> programs(opt.programs.begin(), opt.programs.end());
  auto created = sim::DryRun::create(m, programs, {opt.clamp_index});
  if (!created) {
    fmt::print(stderr, "{}\n", format(created.error()));
    return 2;
  }
  sim::DryRun& run = *created;
  plc::Scenario scenario;
  if (!opt.plc.empty()) {
    auto loaded_scenario = load_scenario(opt.plc, m);
    if (!loaded_scenario) return 2;
    scenario = std::move(*loaded_scenario);
    run.load_scenario(scenario);
  }
  Outputs out;
  if ((!opt.events.empty() && !out.events.open(opt.events)) ||
      (!opt.trace.empty() && !out.trace.open(opt.trace, m, opt.trace_every))) {
    fmt::print(stderr, "nck: error 940002: cannot write the output files ({} / {})\n", opt.events, opt.trace);
    return 2;
  }
  out.report.start(m, opt.programs, !opt.report.empty());
  RunNames names;
  names.run = &run;

  auto o = std::make_unique<kernel::TickOutput>();
  Progress progress(opt.progress);
  const auto wall_start = std::chrono::steady_clock::now();
  bool time_limit = false;
  for (;;) {
    const double t_s = run.time_s();
    run.prepare();
    report_new_warnings(run, t_s, out);
    run.cycle(*o);
    record_events(*o, names, out);
    report_dropped_events(*o, names, out);
    out.trace.write(run.kernel().cycles() - 1, *o);
    out.report.sample(*o);
    if (run.done()) break;
    if (t_s + run.kernel().cycle_time_s() >= opt.max_time_s) {
      time_limit = true;
      break;
    }
    if (opt.realtime)
      std::this_thread::sleep_until(wall_start + std::chrono::duration<double>(t_s));
    progress.update(t_s);
  }
  const double end_s = run.time_s();
  const kernel::Kernel& k = run.kernel();
  if (time_limit) {
    for (std::size_t ch = 0; ch < k.channel_count(); ++ch) {
      if (k.channel_state(ch).status == kernel::ChannelStatus::ended) continue;
      kernel::Event e;
      e.t_s = end_s;
      e.channel = static_cast<std::uint8_t>(ch + 1);
      e.kind = kernel::EventKind::end;
      e.end_reason = kernel::EndReason::max_time;
      out.event(EventWriter::line(e, names), false);
    }
    fmt::print(stderr, "nck: the simulated-time limit of {} s was reached before the program end\n",
               opt.max_time_s);
  }
  out.events.close();
  out.trace.close();
  bool aborted = time_limit;
  for (std::size_t ch = 0; ch < k.channel_count(); ++ch)
    aborted = aborted || k.channel_state(ch).status == kernel::ChannelStatus::aborted;
  const int exit_code = aborted ? 1 : 0;
  if (!opt.report.empty() && !out.report.write(opt.report, end_s, exit_code)) {
    fmt::print(stderr, "nck: error 940002: cannot write {}\n", opt.report);
    return 2;
  }
  if (!opt.final_state.empty() && !write_final(opt.final_state, m, run, end_s, out.errors)) {
    fmt::print(stderr, "nck: error 940002: cannot write {}\n", opt.final_state);
    return 2;
  }
  return exit_code;
}

}  // namespace nck::app
