// nck.check: the pre-flight check of `nck check --json` (app::preflight, the
// command's own walk), its findings as the same dicts.
#include <filesystem>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "nck/run/preflight.hpp"
#include "nck/run/stop_request.hpp"
#include "py_common.hpp"
#include "py_interrupt.hpp"
#include "py_machine.hpp"

namespace nck::py {
namespace {

// A program that is no file raises as Machine.run does (940202): the
// command's bad usage, which writes no JSON.
void check_files(const std::vector<std::string>& programs) {
  for (const std::string& p : programs) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec))
      raise("ProgramError", ErrorId::AppProgramMissing, fmt::format("the program {} does not exist or is not a file", p),
            SourceLoc{p, 0, 0});
  }
}

pyb::list check(const std::string& machine, std::vector<std::string> programs, bool strict, double max_wall_s) {
  if (max_wall_s != 0) check_positive(max_wall_s, "max_wall");
  check_files(programs);
  std::atomic<bool> stop{false};
  app::Preflight p;
  bool wall_reached = false;
  const CtrlC ctrl_c(stop);
  {
    pyb::gil_scoped_release no_gil;
    const app::WallClockLimit wall(max_wall_s, &stop);
    p = app::preflight({machine, programs, {}, 0, strict, &stop});
    wall_reached = wall.reached();
  }
  ctrl_c.raise_if_pressed();
  if (p.bad_usage) raise("ArgumentError", ErrorId::AppBadArgument, p.bad_usage->message);
  if (p.stopped && wall_reached) {  // the command says so and exits 1: here it is one more error found
    const std::size_t ch = p.programs.size();
    p.found.push_back({make_diagnostic(ErrorId::AppWallTimeLimit, SourceLoc{programs[ch], 0, 0},
                                       fmt::format("max_wall {} s reached before the check of this program ended",
                                                   max_wall_s)),
                       ch + 1});
  }
  pyb::list out;
  for (const app::PreflightFinding& f : p.found) out.append(to_python(app::to_json(f)));
  return out;
}

}  // namespace

void bind_check(pyb::module_& m) {
  m.def("check", &check, pyb::arg("machine"), pyb::arg("programs"), pyb::arg("strict"), pyb::arg("max_wall_s"));
}

}  // namespace nck::py
