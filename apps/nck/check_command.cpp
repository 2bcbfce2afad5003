// `nck check`: load the machine, check each channel's program without a
// kernel (app::preflight, which nck.check in Python shares), and list every
// diagnostic found, as text on stderr or as a JSON array on stdout (--json,
// for CI).
#include "check_command.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "nck/output/output_file.hpp"
#include "nck/run/preflight.hpp"
#include "nck/run/stop_request.hpp"

namespace nck::app {
namespace {

void print_found(const Preflight& p, std::size_t from, std::size_t to, bool json) {
  if (json) return;
  for (std::size_t i = from; i < to; ++i) fmt::print(stderr, "{}\n", format(p.found[i].d));
}

// The text the command has always printed: the machine's findings, then per
// program its findings and a summary line (none for a program a stop ended).
void print_report(const CheckOptions& opt, const Preflight& p) {
  std::size_t i = 0;
  while (i < p.found.size() && p.found[i].channel == 0) ++i;
  print_found(p, 0, i, opt.json);
  if (opt.programs.empty() || !p.machine_loaded)
    fmt::print(stderr, "{}: {} error(s), {} warning(s)\n", opt.machine, p.machine_errors, i - p.machine_errors);
  if (p.bad_usage) fmt::print(stderr, "nck: error {}: {}\n", number(p.bad_usage->id), p.bad_usage->message);
  for (const PreflightProgram& prog : p.programs) {
    const std::size_t n = prog.errors + prog.warnings;
    print_found(p, i, i + n, opt.json);
    i += n;
    fmt::print(stderr, "{}: {} block(s), {} error(s), {} warning(s)\n", prog.program, prog.blocks, prog.errors,
               prog.warnings);
  }
}

int stopped_exit_code(const WallClockLimit& wall, const CheckOptions& opt) {
  if (wall.reached()) {
    fmt::print(stderr, "nck: error {}: the wall-clock limit of {} s was reached before the check ended\n",
               number(ErrorId::AppWallTimeLimit), opt.max_wall_s);
    return stop_signal() == 0 ? 1 : signal_exit_code();
  }
  fmt::print(stderr, "nck: interrupted; the check did not end\n");
  return signal_exit_code();
}

}  // namespace

int check_command(const CheckOptions& opt) {
  const WallClockLimit wall(opt.max_wall_s);
  const Preflight p =
      preflight({opt.machine, opt.programs, opt.cycles, opt.clamp_index, opt.strict_keys, &stop_flag()});
  print_report(opt, p);
  if (p.bad_usage) return 2;
  if (p.stopped) return stopped_exit_code(wall, opt);
  if (opt.json) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const PreflightFinding& f : p.found) list.push_back(to_json(f));
    // A closed pipe or a full disk: main_cli reports it (940002, exit 2).
    (void)write_stdout(list.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
  }
  return p.has_errors() ? 1 : 0;
}

}  // namespace nck::app
