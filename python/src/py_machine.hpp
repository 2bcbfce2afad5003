#pragma once
// A loaded, checked machine folder (nck.Machine wraps it): runs programs on
// copies of its data, and opens sessions.
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "nck/config/machine.hpp"
#include "nck/output/output_writers.hpp"
#include "nck/run/run_options.hpp"

namespace nck::py {

struct RunArgs {
  std::vector<std::string> programs;  // one per channel
  std::string plc;
  std::vector<app::RunOptions::PlcText> plc_texts;  // override=, feedhold=, a plc list (before the file)
  std::string trace_columns;                         // "path.v,path.a" (--trace-columns)
  std::optional<std::string> start_at, stop_at;
  std::uint64_t trace_every = 0;  // 0: no trace
  double max_time_s = 86400;
  double max_wall_s = 0;
  double max_trace_mb = 512;
  bool keep_events = true;  // false: Run.events stays empty (a batch needs none)
  double max_events_mb = 256;
};

// A bound in MB (as the API takes it) in bytes.
std::uint64_t mb_bytes(double mb);

struct Machine {
  std::string path;
  config::Machine data;
  std::vector<app::FinalError> warnings;  // of loading: every run reports them too

  // The RunOptions of args, checked (ArgumentError / ProgramError otherwise).
  app::RunOptions options(const RunArgs& args) const;
};

Machine load(const std::string& path);
void bind_machine(pybind11::module_& m);
// A value the API takes only positive and finite (ArgumentError 940201 otherwise).
void check_positive(double v, const char* name);

}  // namespace nck::py
