#pragma once
// The output files of one `nck run` and the rule that protects the inputs.
#include <optional>
#include <string>
#include <vector>

#include "output_writers.hpp"
#include "report_writer.hpp"
#include "run_summary.hpp"
#include "run_command.hpp"
#include "time_by_cause.hpp"

namespace nck::app {

struct RunOutputs {
  EventWriter events;
  TraceWriter trace;
  ReportWriter report;
  std::vector<FinalError> errors;
  RunSummary summary;
  TimeByCause causes;  // every cycle's class, summed (--final, the report, stderr)

  // Events are rendered only when a file wants them.
  bool wants_events() const { return events.is_open() || report.enabled(); }
  void event(const std::string& line, bool is_error) {
    events.write_line(line);
    report.event(line, is_error);
  }
};

// An output path that names an input (a program, the --plc file, a file of
// the machine folder) or another output: the error text (SPEC 2.2: refused,
// exit 2). Paths are compared after resolving links and "..".
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
