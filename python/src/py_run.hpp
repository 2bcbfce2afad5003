#pragma once
// A finished run as Python sees it (nck.Run wraps it): exit code, time,
// errors, events (their JSON lines, as dicts of the JSONL schema or as
// numpy records), the --final document and the trace as numpy arrays; each
// converted to Python when first asked for and kept.
//
// Nothing here changes once the run is made: a property only reads the C++
// result and caches its Python value, so threads sharing a Run need no
// lock (two asking at once may both convert; one value is kept). The
// events' dicts took the C++ events over before, and a second thread that
// came in meanwhile (a gc callback lets another thread run) read freed memory.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include "nck/run/simulation.hpp"

namespace nck::py {

struct RunResult {
  int exit = 0;
  double time_s = 0;
  std::string end;
  std::string summary;                   // the CLI's last stderr line
  std::vector<std::string> messages;     // what nck run would have printed on stderr
  std::vector<app::FinalError> errors, warnings;
  app::EventMemory events;
  nlohmann::json final_state;
  std::vector<std::string> trace_names;
  std::vector<std::shared_ptr<std::vector<double>>> trace_values;  // numpy arrays share them
  bool traced = false;

  // Converted (cached) Python values.
  pybind11::object events_py, records_py, final_py, trace_py;
};

// Everything of a simulation that has finished, moved out of it.
RunResult take_result(app::Simulation& s, const std::vector<app::FinalError>& machine_warnings);

// Events kept as JSON lines, as the dicts of the JSONL schema (one
// json.loads over all of them: far faster than a dict built per field).
pybind11::list event_dicts(const app::EventMemory& m);

void bind_run(pybind11::module_& m);

}  // namespace nck::py
