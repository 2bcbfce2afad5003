#pragma once
// A finished run as Python sees it (nck.Run wraps it): exit code, time,
// errors, events as the JSONL schema's dicts, the --final document and the
// trace as numpy arrays; each converted to Python once, when first asked for.
#include <cstdint>
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
  std::vector<nlohmann::ordered_json> events;
  nlohmann::json final_state;
  std::vector<std::string> trace_names;
  std::vector<std::vector<double>> trace_values;
  bool traced = false;

  // Lazily converted (cached) Python values.
  pybind11::object events_py, final_py, trace_py;
};

// Everything of a simulation that has finished, moved out of it.
RunResult take_result(app::Simulation& s, const std::vector<app::FinalError>& machine_warnings);

void bind_run(pybind11::module_& m);

}  // namespace nck::py
