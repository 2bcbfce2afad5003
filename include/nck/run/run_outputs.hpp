#pragma once
// The output files of one `nck run` and the rule that protects the inputs.
#include <optional>
#include <string>
#include <vector>

#include "nck/output/last_errors.hpp"
#include "nck/output/output_writers.hpp"
#include "nck/output/time_by_cause.hpp"
#include "nck/report/report_writer.hpp"
#include "nck/run/console.hpp"
#include "nck/run/event_memory.hpp"
#include "nck/run/state_document.hpp"
#include "nck/run/run_options.hpp"
#include "nck/run/run_summary.hpp"
#include "nck/run/trace_memory.hpp"

namespace nck::app {

// Where a run's results go: the files of `nck run`, or memory (the Python
// module: events as their JSON lines, the trace as columns, stderr kept).
struct RunOutputs {
  explicit RunOutputs(bool keep_console = false) : console(keep_console) {}
  EventWriter events;
  TraceWriter trace;
  ReportWriter report;
  EventMemory event_memory;    // the Python module's events (off unless started)
  TraceMemory trace_memory;    // the Python module's trace
  std::vector<FinalError> errors;
  std::vector<FinalError> warnings;  // every warning of the run said on stderr (the module's Run.warnings)
  LastErrors last_errors;            // each channel's last error until its reset (a session's state)
  ChannelFrames blocks;              // each channel's block in execution: map and modal state (a session's state)
  RunSummary summary;
  TimeByCause causes;  // every cycle's class, summed (--final, the report, stderr)
  Console console;     // stderr

  // Events are rendered only when an output wants them.
  bool wants_events() const { return event_memory.enabled() || events.is_open() || report.enabled(); }
  void event(const kernel::Event& e, const RunNames& names) { event_line(e, dump_json(EventWriter::object(e, names)), names); }
  // An event already written as its line (block events: BlockEventText).
  void event_line(const kernel::Event& e, const std::string& line, const RunNames& names) {
    events.write_line(line);
    report.event(e, line, names);
    event_memory.add(e, line);
  }
};

// An output path that names an input (a program, the --plc file, a file of
// the machine folder) or another output: the error text (refused with
// exit 2, as README says). Paths are compared after resolving links and "..".
std::optional<std::string> output_path_conflict(const RunOptions& opt);

// The outputs whose target is, at the end of the run, a file the run read:
// a subroutine or cycle the programs called as well as the inputs above,
// compared by device and inode (links, hard links, other spellings). They
// are not written (940004); the others are.
struct OutputsOverInputs {
  bool events = false, trace = false, final_state = false, report = false;
  std::vector<std::string> messages;
  bool any() const { return !messages.empty(); }
};
OutputsOverInputs outputs_over_inputs(const RunOptions& opt, const sim::DryRun& run);

}  // namespace nck::app
