#pragma once
// The output files of one `nck run` and the rule that protects the inputs.
#include <optional>
#include <string>
#include <vector>

#include "output_writers.hpp"
#include "report_writer.hpp"
#include "run_summary.hpp"
#include "run_command.hpp"

namespace nck::app {

struct RunOutputs {
  EventWriter events;
  TraceWriter trace;
  ReportWriter report;
  std::vector<FinalError> errors;
  RunSummary summary;

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

}  // namespace nck::app
