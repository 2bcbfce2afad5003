#include "py_run.hpp"

#include <memory>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "py_common.hpp"

namespace nck::py {
namespace {

// A column handed to numpy without a copy: the array owns the vector.
pyb::array_t<double> column(std::vector<double>&& v) {
  auto* owned = new std::vector<double>(std::move(v));
  pyb::capsule free_when_done(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return pyb::array_t<double>({owned->size()}, {sizeof(double)}, owned->data(), free_when_done);
}

pyb::list error_list(const std::vector<app::FinalError>& es) {
  pyb::list out;
  for (const app::FinalError& e : es) out.append(error_dict(e));
  return out;
}

}  // namespace

RunResult take_result(app::Simulation& s, const std::vector<app::FinalError>& machine_warnings) {
  app::RunOutputs& out = s.outputs();
  RunResult r;
  r.exit = s.exit_code();
  r.time_s = s.run().time_s();
  r.end = s.end_reason();
  r.summary = out.summary.text(r.end, r.time_s);
  r.final_state = s.final_json();
  r.messages = out.console.take();
  for (const std::string& line : out.causes.top_lines()) r.messages.push_back(line);
  r.messages.push_back(r.summary);
  r.errors = out.errors;
  r.warnings = machine_warnings;
  r.warnings.insert(r.warnings.end(), out.warnings.begin(), out.warnings.end());
  r.events = std::move(out.event_list);
  r.traced = out.trace_memory.enabled();
  r.trace_names = std::move(out.trace_memory.names);
  r.trace_values = std::move(out.trace_memory.values);
  return r;
}

void bind_run(pyb::module_& m) {
  pyb::class_<RunResult>(m, "_RunResult")
      .def_readonly("exit", &RunResult::exit)
      .def_readonly("time_s", &RunResult::time_s)
      .def_readonly("end", &RunResult::end)
      .def_readonly("summary", &RunResult::summary)
      .def_readonly("messages", &RunResult::messages)
      .def_property_readonly("errors", [](const RunResult& r) { return error_list(r.errors); })
      .def_property_readonly("warnings", [](const RunResult& r) { return error_list(r.warnings); })
      .def_property_readonly("events", [](RunResult& r) {
        if (!r.events_py) {
          pyb::list l(r.events.size());
          for (std::size_t i = 0; i < r.events.size(); ++i) l[i] = to_python(r.events[i]);
          r.events_py = std::move(l);
          r.events = {};
        }
        return r.events_py;
      })
      .def_property_readonly("final", [](RunResult& r) {
        if (!r.final_py) r.final_py = to_python(r.final_state);
        return r.final_py;
      })
      .def_property_readonly("trace", [](RunResult& r) -> pyb::object {
        if (!r.traced) return pyb::none();
        if (!r.trace_py) {
          pyb::dict d;
          for (std::size_t c = 0; c < r.trace_names.size(); ++c)
            d[pyb::str(r.trace_names[c])] = column(std::move(r.trace_values[c]));
          r.trace_py = std::move(d);
        }
        return r.trace_py;
      });
}

}  // namespace nck::py
