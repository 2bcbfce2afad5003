// `nck check`: load the machine, check each channel's program without a
// kernel, and list every diagnostic found, as text on stderr or as a JSON
// array on stdout (--json, for CI).
#include "check_command.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>

#include "nck/config/load.hpp"
#include "nck/output/output_file.hpp"
#include "nck/prep/program_check.hpp"
#include "nck/run/stop_request.hpp"

namespace nck::app {
namespace {

// A diagnostic and the channel whose program it belongs to (0: machine data).
struct Found {
  Diagnostic d;
  std::size_t channel = 0;
};

nlohmann::json to_json(const Found& f) {
  const ErrorInfo* info = find_error(f.d.id);
  return {{"id", number(f.d.id)},
          {"name", info ? std::string(info->name) : std::string()},
          {"severity", f.d.severity == Severity::error ? "error" : "warning"},
          {"channel", f.channel},
          {"file", f.d.loc.file},
          {"line", f.d.loc.line},
          {"column", f.d.loc.column},
          {"message", f.d.message}};
}

// Every program a regular file, at most one per channel: else bad usage.
bool programs_usable(const CheckOptions& opt, const config::Machine& m) {
  for (const std::string& p : opt.programs) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec)) {
      fmt::print(stderr, "nck: error {}: the program {} does not exist or is not a file\n",
                 number(ErrorId::AppBadUsage), p);
      return false;
    }
  }
  if (opt.programs.size() > m.channels.size()) {
    fmt::print(stderr, "nck: error {}: {} program(s) given for {} channel(s); give one per channel\n",
               number(ErrorId::AppBadUsage), opt.programs.size(), m.channels.size());
    return false;
  }
  return true;
}

// The programs' diagnostics after the machine's; false when a stop ended a check.
bool check_programs(const CheckOptions& opt, const config::Machine& m, std::vector<Found>& found) {
  for (std::size_t ch = 0; ch < opt.programs.size(); ++ch) {
    prep::ProgramCheckResult r =
        prep::check_program(m, ch, opt.programs[ch], {opt.clamp_index, &stop_flag()});
    std::size_t errors = 0, warnings = 0;
    for (Diagnostic& d : r.diagnostics) {
      (d.severity == Severity::error ? errors : warnings) += 1;
      found.push_back({std::move(d), ch + 1});
    }
    if (r.stopped) return false;
    if (!opt.json)
      for (std::size_t i = found.size() - errors - warnings; i < found.size(); ++i)
        fmt::print(stderr, "{}\n", format(found[i].d));
    fmt::print(stderr, "{}: {} block(s), {} error(s), {} warning(s)\n", opt.programs[ch], r.blocks, errors,
               warnings);
  }
  return true;
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
  // Without programs the check says what no program can ask of the machine;
  // with them, each program's check finds where one asks (70252).
  const config::LoadOptions load{opt.strict_keys ? config::KeyPolicy::strict : config::KeyPolicy::lenient,
                                 opt.programs.empty()};
  config::LoadResult loaded = config::load_machine(opt.machine, load);
  std::vector<Found> found;
  for (const Diagnostic& d : loaded.diagnostics.items()) {
    if (!opt.json) fmt::print(stderr, "{}\n", format(d));
    found.push_back({d, 0});
  }
  const std::size_t machine_errors = loaded.diagnostics.error_count();
  if (opt.programs.empty() || !loaded.ok())
    fmt::print(stderr, "{}: {} error(s), {} warning(s)\n", opt.machine, machine_errors,
               found.size() - machine_errors);
  if (loaded.ok()) {
    for (const std::string& dir : opt.cycles) loaded.machine->cycle_paths.emplace_back(dir);
    if (!programs_usable(opt, *loaded.machine)) return 2;
    const WallClockLimit wall(opt.max_wall_s);
    if (!check_programs(opt, *loaded.machine, found)) return stopped_exit_code(wall, opt);
  }
  bool errors = false;
  nlohmann::json list = nlohmann::json::array();
  for (const Found& f : found) {
    errors = errors || f.d.severity == Severity::error;
    if (opt.json) list.push_back(to_json(f));
  }
  // A closed pipe or a full disk: main_cli reports it (940002, exit 2).
  if (opt.json)
    (void)write_stdout(list.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  return errors ? 1 : 0;
}

}  // namespace nck::app
