// `nck run`: load the machine, decode each channel's program, tick the
// kernel until every channel ends (or a limit or a signal stops the run), and
// write events, trace, report and final state, always complete.
#include "run_command.hpp"

#include <filesystem>
#include <fmt/format.h>

#include "nck/config/load.hpp"
#include "nck/output/output_writers.hpp"
#include "nck/run/run_outputs.hpp"
#include "nck/run/simulation.hpp"

namespace nck::app {
namespace {

bool print_load_diagnostics(const config::LoadResult& r) {
  for (const Diagnostic& d : r.diagnostics.items()) fmt::print(stderr, "{}\n", format(d));
  return r.ok();
}

// Completes every output file; a file that cannot be written is error 940002
// and exit 2 (an interrupted run keeps 130/143).
int finish_outputs(Simulation& s) {
  const RunOptions& opt = s.options();
  RunOutputs& out = s.outputs();
  const sim::DryRun& run = s.run();
  int code = s.exit_code();
  const double end_s = run.time_s();
  std::vector<std::string> failures;
  // Only now are all the files known that the programs called.
  const OutputsOverInputs over = outputs_over_inputs(opt, run);
  if (over.events) out.events.discard();
  else if (auto e = out.events.commit()) failures.push_back(*e);
  if (over.trace) out.trace.discard();
  else if (auto e = out.trace.commit()) failures.push_back(*e);
  const bool want_causes = !opt.final_state.empty() || !opt.report.empty();
  const nlohmann::ordered_json causes = want_causes ? out.causes.json() : nlohmann::ordered_json::object();
  out.report.set_causes(causes);
  if (!over.report)
    if (auto e = out.report.write(opt.report, end_s, code)) failures.push_back(*e);
  if (!opt.final_state.empty() && !over.final_state)
    if (auto e = write_final(opt.final_state, s.machine(), run, end_s, s.end_reason(), out.errors, causes))
      failures.push_back(*e);
  for (const std::string& f : failures) fmt::print(stderr, "nck: error {}: {}\n", number(ErrorId::AppOutputFile), f);
  for (const std::string& f : over.messages)
    fmt::print(stderr, "nck: error {}: {}\n", number(ErrorId::AppOutputPathConflict), f);
  // the top causes first: the summary stays the last line (scripts read it)
  for (const std::string& line : out.causes.top_lines()) fmt::print(stderr, "{}\n", line);
  fmt::print(stderr, "{}\n", out.summary.text(s.end_reason(), end_s));
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
  config::LoadResult loaded = config::load_machine(
      opt.machine, {opt.strict_keys ? config::KeyPolicy::strict : config::KeyPolicy::lenient});
  if (!print_load_diagnostics(loaded)) return 2;
  auto created = Simulation::create(std::move(*loaded.machine), opt);
  if (!created) {
    for (const Diagnostic& d : created.error().items()) fmt::print(stderr, "{}\n", cli_text(d));
    return 2;
  }
  Simulation& s = **created;
  RunOutputs& out = s.outputs();
  for (const Diagnostic& d : loaded.diagnostics.items())  // printed above; the summary counts them too
    if (d.severity == Severity::warning) out.summary.warning();
  std::optional<std::string> open_error;
  if (!opt.events.empty()) open_error = out.events.open(opt.events, opt.realtime);
  if (!open_error && !opt.trace.empty())
    open_error = out.trace.open(opt.trace, opt.realtime, s.machine(), opt.trace_every,
                                opt.trace_columns.empty() ? TraceColumns{}
                                                          : parse_trace_columns(opt.trace_columns).value_or(TraceColumns{}));
  if (open_error) {
    fmt::print(stderr, "nck: error {}: {}\n", number(ErrorId::AppOutputFile), *open_error);
    return 2;
  }
  if (!opt.report.empty()) out.report.start(s.machine(), {opt.machine, opt.plc, opt.programs}, s.run());
  if (opt.ghost) out.report.set_ghost(*opt.ghost);
  s.finish(s.run_to_end());
  return finish_outputs(s);
}

}  // namespace nck::app
