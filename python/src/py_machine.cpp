#include "py_machine.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "nck/config/load.hpp"
#include "nck/output/trace_columns.hpp"
#include "nck/run/simulation.hpp"
#include "nck/run/start_at.hpp"
#include "nck/run/stop_request.hpp"
#include "py_common.hpp"
#include "py_interrupt.hpp"
#include "py_run.hpp"

namespace nck::py {
namespace {

// N100[:pass][@prog] (type 4), block:K (type 3) or offset:BYTES[...] (type 1).
prep::SearchMark start_mark(const std::string& text) {
  std::optional<prep::SearchMark> m;
  if (text.starts_with("block:")) m = app::parse_start_at_block(std::string_view(text).substr(6));
  else if (text.starts_with("offset:")) m = app::parse_start_at_offset(std::string_view(text).substr(7));
  else m = app::parse_start_at(text);
  if (!m)
    raise("ArgumentError", ErrorId::AppBadArgument,
          fmt::format("start_at '{}' is none of N<n>[:<pass>][@<program>], block:<K>, offset:<bytes>", text));
  return *m;
}

}  // namespace

void check_positive(double v, const char* name) {
  if (!(v > 0) || !std::isfinite(v))
    raise("ArgumentError", ErrorId::AppBadArgument, fmt::format("{} must be a positive number, not {}", name, v));
}

std::uint64_t mb_bytes(double mb) { return static_cast<std::uint64_t>(std::min(mb * 1024 * 1024, 0x1p62)); }

app::RunOptions Machine::options(const RunArgs& a) const {
  app::RunOptions o;
  o.machine = path;
  o.programs = a.programs;
  for (const std::string& p : a.programs) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec))
      raise("ProgramError", ErrorId::AppProgramMissing, fmt::format("the program {} does not exist or is not a file", p),
            SourceLoc{p, 0, 0});
  }
  if (a.programs.size() > data.channels.size())
    raise("ArgumentError", ErrorId::AppBadArgument,
          fmt::format("{} programs for {} channel(s)", a.programs.size(), data.channels.size()));
  o.plc = a.plc;
  o.plc_texts = a.plc_texts;
  if (!a.trace_columns.empty()) {
    const auto columns = app::parse_trace_columns(a.trace_columns);
    if (!columns) raise("ArgumentError", ErrorId::AppBadArgument, "trace_columns: " + columns.error());
    o.trace_columns = a.trace_columns;
  }
  if (a.start_at) o.start_at = start_mark(*a.start_at);
  if (a.stop_at) {
    o.stop_at = app::parse_stop_at(*a.stop_at);
    if (!o.stop_at)
      raise("ArgumentError", ErrorId::AppBadArgument,
            fmt::format("stop_at '{}' is none of N<n>, line:<L>, block:<K>, event:<kind>", *a.stop_at));
  }
  check_positive(a.max_time_s, "max_time");
  if (a.max_wall_s != 0) check_positive(a.max_wall_s, "max_wall");
  check_positive(a.max_trace_mb, "max_trace_mb");
  check_positive(a.max_events_mb, "max_events_mb");
  o.max_time_s = a.max_time_s;
  o.max_wall_s = a.max_wall_s;
  o.trace_every = a.trace_every;
  o.progress = false;
  return o;
}

Machine load(const std::string& path) {
  config::LoadResult r = config::load_machine(path);
  if (!r.ok()) {
    NckError e{"ConfigError", {}};
    for (const Diagnostic& d : r.diagnostics.items())
      if (d.severity == Severity::error) e.diagnostics.push_back(d);
    if (e.diagnostics.empty())
      e.diagnostics.push_back(make_diagnostic(ErrorId::AppBadUsage, {path, 0, 0}, "the machine folder cannot be loaded"));
    throw e;
  }
  Machine m{path, std::move(*r.machine), {}};
  for (const Diagnostic& d : r.diagnostics.items())
    m.warnings.push_back(app::FinalError{number(d.id), 0, d.loc.line, d.loc.file, d.message});
  return m;
}

// The simulation's setup errors as the exception that fits them.
[[noreturn]] void raise_setup(const Diagnostics& ds) {
  NckError e{"ProgramError", {}};
  for (const Diagnostic& d : ds.items())
    if (d.severity == Severity::error) e.diagnostics.push_back(d);
  if (!e.diagnostics.empty() && e.diagnostics.front().id == ErrorId::AppBadUsage) e.kind = "ArgumentError";
  throw e;
}

RunResult run(const Machine& m, const RunArgs& args) {
  const app::RunOptions opt = m.options(args);
  auto created = app::Simulation::create(m.data, opt, app::Simulation::Host::embedded);
  if (!created) raise_setup(created.error());
  app::Simulation& s = **created;
  if (args.keep_events) s.outputs().event_memory.start(mb_bytes(args.max_events_mb), app::EventMemory::Full::end_run);
  if (args.trace_every > 0)
    s.outputs().trace_memory.start(s.machine(), args.trace_every, mb_bytes(args.max_trace_mb),
                                   app::parse_trace_columns(opt.trace_columns).value_or(app::TraceColumns{}));
  for (std::size_t i = 0; i < m.warnings.size(); ++i) s.outputs().summary.warning();
  const CtrlC ctrl_c(*s.own_stop_flag());  // ends the run as a wall-clock limit would
  {
    pyb::gil_scoped_release no_gil;  // other Python threads run meanwhile
    s.finish(s.run_to_end());
  }
  ctrl_c.raise_if_pressed();
  return take_result(s, m.warnings);
}

void bind_machine(pyb::module_& mod) {
  pyb::class_<Machine>(mod, "_Machine")
      .def(pyb::init(&load), pyb::arg("path"))
      .def_readonly("path", &Machine::path)
      .def_property_readonly("channels",
                             [](const Machine& m) {
                               pyb::list out;
                               for (const config::ChannelConfig& c : m.data.channels) {
                                 pyb::list axes;
                                 for (const auto& a : c.axes) axes.append(a.name);
                                 out.append(axes);
                               }
                               return out;
                             })
      .def_property_readonly("warnings",
                             [](const Machine& m) {
                               pyb::list out;
                               for (const app::FinalError& w : m.warnings) out.append(error_dict(w, Severity::warning));
                               return out;
                             })
      .def(
          "run",
          [](const Machine& m, std::vector<std::string> programs, std::string plc,
             const std::vector<std::pair<std::string, std::string>>& plc_texts, std::optional<std::string> start_at,
             std::optional<std::string> stop_at, std::uint64_t trace_every, std::string trace_columns,
             double max_time_s, double max_wall_s, double max_trace_mb, bool keep_events, double max_events_mb) {
            RunArgs a{std::move(programs), std::move(plc), {}, std::move(trace_columns), std::move(start_at),
                      std::move(stop_at), trace_every, max_time_s, max_wall_s, max_trace_mb, keep_events,
                      max_events_mb};
            for (const auto& [name, text] : plc_texts) a.plc_texts.push_back({name, text});
            return run(m, a);
          },
          pyb::arg("programs"), pyb::arg("plc"), pyb::arg("plc_texts"), pyb::arg("start_at"), pyb::arg("stop_at"),
          pyb::arg("trace_every"), pyb::arg("trace_columns"), pyb::arg("max_time_s"), pyb::arg("max_wall_s"),
          pyb::arg("max_trace_mb"), pyb::arg("keep_events"), pyb::arg("max_events_mb"));
}

}  // namespace nck::py
