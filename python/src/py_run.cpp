#include "py_run.hpp"

#include <cstring>
#include <memory>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "py_common.hpp"

namespace nck::py {
namespace {

// A column handed to numpy without a copy: the array shares the vector.
pyb::array_t<double> column(const std::shared_ptr<std::vector<double>>& v) {
  auto* owner = new std::shared_ptr<std::vector<double>>(v);
  pyb::capsule release(owner, [](void* p) { delete static_cast<std::shared_ptr<std::vector<double>>*>(p); });
  return pyb::array_t<double>({v->size()}, {sizeof(double)}, v->data(), release);
}

pyb::list error_list(const std::vector<app::FinalError>& es, Severity severity) {
  pyb::list out;
  for (const app::FinalError& e : es) out.append(error_dict(e, severity));
  return out;
}

pyb::object json_loads(std::string_view text) {
  const pyb::object loads = pyb::module_::import("json").attr("loads");
  return loads(pyb::reinterpret_steal<pyb::str>(
      PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "replace")));
}

// One row of Run.event_records: 22 bytes, numpy's packed layout of kRecordFields.
#pragma pack(push, 1)
struct PackedRecord {
  double t;
  std::uint8_t ch;
  std::uint8_t ev;
  std::uint32_t line;
  std::int64_t n;
};
#pragma pack(pop)

pyb::dtype record_dtype() {
  pyb::list fields;
  for (const auto& [name, type] : {std::pair{"t", "<f8"}, {"ch", "u1"}, {"ev", "u1"}, {"line", "<u4"}, {"n", "<i8"}})
    fields.append(pyb::make_tuple(name, type));
  pyb::dtype dt = pyb::dtype::from_args(fields);
  if (dt.itemsize() != static_cast<pyb::ssize_t>(sizeof(PackedRecord)))
    throw std::logic_error("Run.event_records: numpy's layout is not PackedRecord's");
  return dt;
}

pyb::array event_records(const app::EventMemory& m) {
  pyb::array out(record_dtype(), std::vector<pyb::ssize_t>{static_cast<pyb::ssize_t>(m.size())}, std::vector<pyb::ssize_t>{});
  auto* row = static_cast<PackedRecord*>(out.mutable_data());
  for (std::size_t i = 0; i < m.size(); ++i) {
    const app::EventRecord& r = m.records[i];
    const PackedRecord p{r.t_s, r.channel, r.kind, r.line, r.n};
    std::memcpy(row + i, &p, sizeof p);
  }
  return out;
}

pyb::object event_at(const app::EventMemory& m, std::int64_t i) {
  const auto n = static_cast<std::int64_t>(m.size());
  if (i < -n || i >= n)
    raise("ArgumentError", ErrorId::AppBadArgument, fmt::format("event({}): the run kept {} event(s)", i, n));
  return json_loads(m.line(static_cast<std::size_t>(i < 0 ? i + n : i)));
}

}  // namespace

pyb::list event_dicts(const app::EventMemory& m) {
  std::string array = "[";
  array.reserve(m.text.size() + m.size() + 2);
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (i > 0) array += ',';
    array += m.line(i);
  }
  array += ']';
  return json_loads(array);
}

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
  r.events = std::move(out.event_memory);
  r.traced = out.trace_memory.enabled();
  r.trace_names = std::move(out.trace_memory.names);
  for (std::vector<double>& c : out.trace_memory.values)
    r.trace_values.push_back(std::make_shared<std::vector<double>>(std::move(c)));
  return r;
}

void bind_run(pyb::module_& m) {
  // numpy's C API, found once now, while the import holds every other
  // thread out: found on first use, its static guard was held across
  // numpy's import, which lets other threads run; one that came for the
  // guard with the GIL deadlocked (two threads reading event_records).
  (void)pyb::detail::npy_api::get();
  pyb::list kinds;
  for (std::size_t k = 0; k < std::variant_size_v<kernel::EventPayload>; ++k)
    kinds.append(kernel::event_name(static_cast<kernel::EventKind>(k)));
  kinds.append(app::kOperatorEventName);  // a session's operator actions (index kOperatorEventKind)
  m.attr("EVENT_KINDS") = pyb::tuple(kinds);
  pyb::class_<RunResult>(m, "_RunResult")
      .def_readonly("exit", &RunResult::exit)
      .def_readonly("time_s", &RunResult::time_s)
      .def_readonly("end", &RunResult::end)
      .def_readonly("summary", &RunResult::summary)
      .def_readonly("messages", &RunResult::messages)
      .def_property_readonly("errors", [](const RunResult& r) { return error_list(r.errors, Severity::error); })
      .def_property_readonly("warnings", [](const RunResult& r) { return error_list(r.warnings, Severity::warning); })
      .def_property_readonly("events", [](RunResult& r) {
        if (!r.events_py) r.events_py = event_dicts(r.events);
        return r.events_py;
      })
      .def_property_readonly("event_records", [](RunResult& r) {
        if (!r.records_py) r.records_py = event_records(r.events);
        return r.records_py;
      })
      .def("event", [](const RunResult& r, std::int64_t i) { return event_at(r.events, i); }, pyb::arg("i"))
      .def_property_readonly("event_bytes", [](const RunResult& r) { return r.events.bytes(); })
      .def_property_readonly("final", [](RunResult& r) {
        if (!r.final_py) r.final_py = to_python(r.final_state);
        return r.final_py;
      })
      .def_property_readonly("trace", [](RunResult& r) -> pyb::object {
        if (!r.traced) return pyb::none();
        if (!r.trace_py) {
          pyb::dict d;
          for (std::size_t c = 0; c < r.trace_names.size(); ++c) d[pyb::str(r.trace_names[c])] = column(r.trace_values[c]);
          r.trace_py = std::move(d);
        }
        return r.trace_py;
      });
}

}  // namespace nck::py
