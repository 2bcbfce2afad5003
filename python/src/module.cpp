// _nck: the compiled half of the nck package (python/nck/ is the other):
// the library `nck` itself uses, in-process.
#include <filesystem>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "nck/config/load.hpp"
#include "nck/config/parameter_registry.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/core/version.hpp"
#include "nck/nc/block_json.hpp"
#include "nck/nc/decoder.hpp"
#include "nck/output/diagnostic_json.hpp"
#include "nck/prep/decoder_setup.hpp"
#include "nck/run/stop_request.hpp"
#include "py_common.hpp"
#include "py_interrupt.hpp"
#include "py_machine.hpp"

namespace nck::py {

void bind_run(pyb::module_& m);
void bind_session(pyb::module_& m);
void bind_check(pyb::module_& m);

namespace {

// nck parse --json: the blocks as dicts; errors raise ProgramError with
// every diagnostic (decoding goes on past a bad block, as nck parse does).
// Ctrl-C stops the decoder at its next block (KeyboardInterrupt).
pyb::list parse(const std::string& program, const Machine* machine, std::size_t channel, double max_wall_s) {
  if (max_wall_s != 0) check_positive(max_wall_s, "max_wall");
  nc::DecoderConfig cfg;
  cfg.axis_names = {"X", "Y", "Z", "A", "B", "C", "U", "V", "W"};
  cfg.spindle_names = {"S1", "S2", "S3"};
  cfg.main_spindle = "S1";
  if (machine) {
    if (channel == 0 || channel > machine->data.channels.size())
      raise("ArgumentError", ErrorId::AppBadArgument, fmt::format("the machine has no channel {}", channel));
    cfg = prep::decoder_config(machine->data, channel - 1);
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(program, ec))
    raise("ProgramError", ErrorId::AppProgramMissing, "the program does not exist or is not a file", {program, 0, 0});
  std::atomic<bool> stop{false};
  cfg.continue_after_error = true;
  cfg.stop = &stop;
  std::vector<nlohmann::json> blocks;
  std::vector<Diagnostic> diagnostics;
  const CtrlC ctrl_c(stop);
  {
    pyb::gil_scoped_release no_gil;
    const app::WallClockLimit wall(max_wall_s, &stop);
    nc::Decoder dec(program, cfg);
    for (;;) {
      nc::Decoder::Result res = dec.next();
      if (res.status == nc::Decoder::Status::error && dec.can_continue()) continue;
      if (res.status != nc::Decoder::Status::block) break;
      blocks.push_back(nc::to_json(res.block, dec));
      if (res.block.program_end) break;
    }
    diagnostics = dec.diagnostics();
    if (wall.reached())
      diagnostics.push_back(make_diagnostic(ErrorId::AppWallTimeLimit, {program, 0, 0},
                                            fmt::format("max_wall {} s reached after {} block(s)", max_wall_s, blocks.size())));
  }
  ctrl_c.raise_if_pressed();
  NckError failed{"ProgramError", {}};
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::error) failed.diagnostics.push_back(d);
  if (!failed.diagnostics.empty()) throw failed;
  pyb::list out;
  for (const nlohmann::json& b : blocks) out.append(to_python(b));
  return out;
}

pyb::list errors() {
  pyb::list out;
  // The catalogue's one shape, as GET /api/v1/errors (app::catalogue_json),
  // and `text`, the name the cause had here before.
  for (const ErrorInfo& e : all_errors()) {
    nlohmann::ordered_json j = app::catalogue_json(e);
    j["text"] = std::string(e.text);
    out.append(to_python(j));
  }
  return out;
}

pyb::list params() {
  pyb::list out;
  for (const config::ParamInfo& p : config::all_parameters()) {
    pyb::dict d;
    d["key"] = std::string(p.key);
    d["id"] = std::string(p.id);
    d["list"] = std::string(config::list_name(p.list));
    d["min"] = p.min;
    d["max"] = p.max;
    d["default"] = p.text_default.empty() ? pyb::object(pyb::float_(p.def)) : pyb::object(pyb::str(std::string(p.text_default)));
    d["unit"] = std::string(p.list_unit);
    d["meaning"] = std::string(p.meaning);
    out.append(d);
  }
  return out;
}

}  // namespace

}  // namespace nck::py

PYBIND11_MODULE(_nck, m) {
  namespace py = nck::py;
  m.doc() = "The compiled core of the nck package; use `import nck`.";
  py::register_errors();
  py::bind_machine(m);
  py::bind_run(m);
  py::bind_session(m);
  py::bind_check(m);
  m.def("parse", &py::parse, pybind11::arg("program"), pybind11::arg("machine"), pybind11::arg("channel"),
        pybind11::arg("max_wall_s"));
  m.def("errors", &py::errors);
  m.def("params", &py::params);
  m.def("errors_markdown", &nck::errors_markdown);
  m.attr("version") = std::string(nck::version());
  m.attr("git_hash") = std::string(nck::git_hash());
}
