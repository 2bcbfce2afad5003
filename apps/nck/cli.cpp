// The nck command line (README, docs/cli.md). Exit codes: 0 ok, 1 errors in the input
// (NC error, plausibility errors), 2 bad usage or machine data.
#include "cli.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "nck/config/machine.hpp"
#include "nck/core/diagnostic.hpp"
#include "nck/core/edit_distance.hpp"
#include "nck/core/version.hpp"
#include "nck/output/trace_columns.hpp"
#include "nck/run/start_at.hpp"
#include "nck/run/stop_request.hpp"
#include "check_command.hpp"
#include "commands.hpp"
#include "diff_command.hpp"
#include "run_command.hpp"
#include "serve_command.hpp"

namespace nck::app {
namespace {

// What a command printed on stdout must have arrived (a full disk, a closed
// pipe): checked once, at the end, for every command.
bool stdout_written() {
  if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return true;
  // fprintf, not fmt::print: a broken stderr too must not throw here.
  std::fprintf(stderr, "nck: error %u: cannot write to stdout: %s\n", number(ErrorId::AppOutputFile),
               std::strerror(errno != 0 ? errno : EIO));
  return false;
}

// The known word nearest to `word`, if it is a plausible typo of it.
std::string nearest(const std::string& word, const std::vector<std::string>& known) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;  // at most a third of it wrong
  for (const std::string& k : known) {
    const std::size_t d = edit_distance(word, k, best_d);
    if (d < best_d) best_d = d, best = k;
  }
  return best;
}

std::vector<const CLI::App*> subcommands(const CLI::App& app) {
  return app.get_subcommands([](const CLI::App*) { return true; });
}

// A command's long options ("--report", ...).
std::vector<std::string> long_options(const CLI::App& command) {
  std::vector<std::string> out;
  for (const CLI::Option* o : command.get_options())
    for (const std::string& n : o->get_lnames()) out.push_back("--" + n);
  return out;
}

bool contains(const std::vector<std::string>& words, const std::string& w) {
  return std::find(words.begin(), words.end(), w) != words.end();
}

// A hint for one word of the command line given to `sub` (nullptr: before
// any command), else "". A long option written with one dash ("-report")
// is taken as the long option it means, of this command or of another one.
std::string option_hint(const CLI::App& app, const CLI::App* sub, const std::string& given) {
  std::string arg = given.substr(0, given.find('='));
  const bool one_dash = arg.size() > 2 && arg[0] == '-' && arg[1] != '-';
  if (one_dash) arg = "-" + arg;
  if (arg.rfind("--", 0) != 0) return {};
  const std::vector<std::string> own = sub ? long_options(*sub) : std::vector<std::string>{};
  if (contains(own, arg)) return one_dash ? fmt::format(" (did you mean '{}'?)", arg) : std::string();
  if (const std::string guess = nearest(arg, own); !guess.empty()) return fmt::format(" (did you mean '{}'?)", guess);
  for (const CLI::App* c : subcommands(app))
    if (c != sub && contains(long_options(*c), arg))
      return fmt::format(" (did you mean '{}'? It is an option of 'nck {}')", arg, c->get_name());
  return {};
}

// A hint for a mistyped subcommand or option (" (did you mean ...?)"), else "".
std::string did_you_mean(const CLI::App& app, int argc, char** argv) {
  if (argc < 2) return {};
  std::vector<std::string> commands;
  const CLI::App* sub = nullptr;
  for (const CLI::App* c : subcommands(app)) {
    commands.push_back(c->get_name());
    if (c->get_name() == argv[1]) sub = c;
  }
  const std::string first = argv[1];
  if (first.rfind('-', 0) != 0 && !sub) {
    const std::string guess = nearest(first, commands);
    return guess.empty() ? fmt::format(": '{}' is not one of {}", first, fmt::join(commands, ", "))
                         : fmt::format(": '{}' is not one (did you mean '{}'?)", first, guess);
  }
  for (int i = sub ? 2 : 1; i < argc; ++i)
    if (std::string hint = option_hint(app, sub, argv[i]); !hint.empty()) return hint;
  return {};
}

constexpr const char* kStrictHelp =
    "every unknown list key is an error (910032), not only a misspelt one (910031); without it a key nck does "
    "not model is warning 910002";

// A number option's check, with messages a user reads at a glance ("must be
// >= 1", "'abc' is not a number") instead of CLI11's range of doubles.
CLI::Validator number_at_least(double min, bool whole) {
  return CLI::Validator(
      [min, whole](std::string& text) -> std::string {
        double value = 0;
        const char* end = text.data() + text.size();
        if (auto [p, ec] = std::from_chars(text.data(), end, value); ec == std::errc::result_out_of_range)
          return fmt::format("'{}' is too large", text);
        else if (ec != std::errc{} || p != end || !std::isfinite(value))
          return fmt::format("'{}' is not a number", text);
        if (value < min) return fmt::format("must be ≥ {}, not {}", min, text);
        // Whole-number options land in 32- or 64-bit counters: stay far below both.
        constexpr auto kMaxWhole = std::numeric_limits<std::uint32_t>::max();
        if (whole && value > kMaxWhole) return fmt::format("'{}' is too large (at most {})", text, kMaxWhole);
        if (whole && value != std::floor(value)) return fmt::format("'{}' is not a whole number", text);
        return {};
      },
      whole ? fmt::format("INTEGER >= {}", min) : fmt::format("NUMBER >= {}", min));
}

// --start-mode: a P-CHAN-00508 symbol (SV only with a block search).
CLI::Validator start_mode_validator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::string mode = config::canonical_start_mode(text);
        if (mode.empty()) return fmt::format("'{}' is no start mode of fct_condition (P-CHAN-00508)", text);
        text = mode;
        return {};
      },
      "MODE");
}

// A block-search mark: parse(text) must accept it.
template <class Parse>
CLI::Validator mark_validator(Parse parse, const char* forms) {
  return CLI::Validator(
      [parse, forms](std::string& text) -> std::string {
        if (parse(text)) return {};
        return fmt::format("'{}' is no block-search mark: {}", text, forms);
      },
      "MARK");
}

CLI::Validator stop_at_validator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (parse_stop_at(text)) return {};
        return fmt::format("'{}' is no stop mark: N<n>, line:<L>, block:<K> or event:<kind> (e.g. event:wait)",
                           text);
      },
      "MARK");
}

// --start-at N<n>[:pass][@prog], --start-at-block K, --start-at-offset
// BYTES[:pass][@prog] (one of them) and --covered PCT.
void add_block_search_options(CLI::App& runc, RunOptions& run) {
  auto* n = runc.add_option_function<std::string>(
                    "--start-at", [&run](const std::string& t) { run.start_at = parse_start_at(t); },
                    "block search: run without motion up to block N<n>[:<pass>][@<program>], return to the "
                    "contour and go on from there")
                ->check(mark_validator(parse_start_at, "N<n>[:<pass>][@<program>], e.g. N100, N100:2@sub.nc"));
  auto* k = runc.add_option_function<std::string>(
                    "--start-at-block", [&run](const std::string& t) { run.start_at = parse_start_at_block(t); },
                    "block search to the K-th NC row read (block counter: comment and empty rows, loop passes "
                    "and subroutine rows count)")
                ->check(mark_validator(parse_start_at_block, "a whole number >= 1"))
                ->excludes(n);
  runc.add_option_function<std::string>(
          "--start-at-offset", [&run](const std::string& t) { run.start_at = parse_start_at_offset(t); },
          "block search to the block at byte offset BYTES[:<pass>][@<program>] of the main program (or <program>)")
      ->check(mark_validator(parse_start_at_offset, "BYTES[:<pass>][@<program>]"))
      ->excludes(n)
      ->excludes(k);
  runc.add_option_function<double>(
          "--covered", [&run](double pct) { run.covered_pct = pct; },
          "with a block search: the share of the restart block's path already done, 0..100 %")
      ->check(CLI::Range(0.0, 100.0));
}

}  // namespace

int main_cli(int argc, char** argv) {
  install_signal_handlers();  // before anything that a signal could leave half done
  CLI::App app{"nck - an open NC kernel: check machine data, decode and run NC programs"};
  app.require_subcommand(1);
  app.set_version_flag("--version", fmt::format("nck {} (git {})", nck::version(), nck::git_hash()));

  CheckOptions checko;
  auto* check = app.add_subcommand(
      "check", "Check a machine folder and, without running them, its NC programs: every error and warning");
  check->add_option("MACHINE", checko.machine, "machine folder (with startup.lis)")->required();
  check->add_option("PROGRAM", checko.programs, "NC program per channel (PROGRAM2 is channel 2's...)");
  check->add_flag("--json", checko.json, "print the diagnostics as a JSON array on stdout (for CI)");
  check->add_option("--cycles", checko.cycles,
                    "search DIR for L CYCLE files (after the machine's cycle_path[i]); repeat")
      ->allow_extra_args(false);
  check->add_option("--clamp-index", checko.clamp_index, "clamp-offset group pzv_grp[N] at program start")
      ->check(number_at_least(0, true));
  check->add_option("--max-wall", checko.max_wall_s, "wall-clock limit in seconds")
      ->check(number_at_least(0.001, false));
  check->add_flag("--strict", checko.strict_keys, kStrictHelp);
  check->footer(
      "Diagnostics go to stderr (FILE:LINE: error|warning ID: text), or with --json to stdout. Exit 0: no "
      "errors (warnings allowed), 1: errors found, 2: bad usage (docs/cli.md).");

  RunOptions run;
  auto* runc = app.add_subcommand("run", "Run NC programs on a machine, cycle by cycle");
  runc->add_option("MACHINE", run.machine, "machine folder (with startup.lis)")->required();
  runc->add_option("PROGRAM", run.programs,
                   "NC program per channel (PROGRAM2 runs in channel 2...); none: the --plc scenario's mdi lines");
  runc->add_option("--events", run.events, "write events as JSON lines to FILE (- for stdout)")->type_name("FILE");
  runc->add_option("--trace", run.trace, "write set points as CSV to FILE (- for stdout)")->type_name("FILE");
  runc->add_option("--trace-every", run.trace_every, "trace every Nth cycle")->check(number_at_least(1, true));
  runc->add_option("--trace-columns", run.trace_columns, "extra trace columns: path.v,path.a,path.j (path velocity, acceleration, jerk)")
      ->type_name("LIST")
      ->check(CLI::Validator(
          [](const std::string& v) {
            auto c = parse_trace_columns(v);
            return c ? std::string() : c.error();
          },
          "LIST"));
  runc->add_option("--final", run.final_state, "write the final state as JSON to FILE (- for stdout)")->type_name("FILE");
  runc->add_option("--plc", run.plc, "timed HLI actions (docs/plc-scenario.md)");
  runc->add_option("--report", run.report, "write a self-contained HTML report with plots to FILE (- for stdout)")->type_name("FILE");
  runc->add_option("--max-time", run.max_time_s, "simulated-time limit in seconds")
      ->check(number_at_least(0.001, false));
  runc->add_option("--max-wall", run.max_wall_s, "wall-clock limit in seconds")->check(number_at_least(0.001, false));
  runc->add_flag("--realtime", run.realtime, "pace the cycles to the wall clock");
  runc->add_flag("--prep-thread", run.prep_thread,
                 "decode and plan in a thread of their own (the same outputs while preparation keeps up)");
  runc->add_flag("--unhomed", run.unhomed,
                 "start with no axis homed: a programmed motion of an axis with kenngr.prog_move_requires_homing "
                 "is refused (930740) until G74 homes it");
  runc->add_option("--clamp-index", run.clamp_index, "clamp-offset group pzv_grp[N] at program start")
      ->check(number_at_least(0, true));
  runc->add_flag("!--no-progress", run.progress, "no progress display on the terminal");
  runc->add_option("--start-mode", run.start_mode,
                   "program-start mode for fct_condition[i] (P-CHAN-00508): ISG_STANDARD (default), "
                   "DRY_RUN, CONTOUR_VISU, SYNTAX_CHECK, PROD_TIME, ONLINE_PROD_TIME, ON_LINE, SCENE")
      ->check(start_mode_validator());
  runc->add_option_function<std::string>(
          "--stop-at", [&run](const std::string& text) { run.stop_at = parse_stop_at(text); },
          "end the run where this block ends: N<n>, line:<L>, block:<K> or event:<kind> (end reason stop_at)")
      ->check(stop_at_validator());
  add_block_search_options(*runc, run);
  runc->add_option("--cycles", run.cycles, "search DIR for L CYCLE files (after the machine's cycle_path[i]); repeat")
      ->allow_extra_args(false);
  runc->add_flag("--strict", run.strict_keys, kStrictHelp);
  runc->footer(
      "FILE - writes that output to stdout (one output at a time); diagnostics and the progress line stay on "
      "stderr.");

  DiffOptions diffo;
  auto* diffc = app.add_subcommand(
      "diff", "Compare two runs: cycle time and time by cause per cause, tool, subroutine and block");
  diffc->add_option("INPUT", diffo.inputs,
                    "A.json B.json (two nck run --final files), or with --run MACHINE_A PROGRAM_A MACHINE_B PROGRAM_B")
      ->required();
  diffc->add_flag("--run", diffo.run, "run both machine/program pairs first; also compare their paths");
  diffc->add_flag("--json", diffo.json, "print the comparison as JSON on stdout");
  diffc->add_option("--report", diffo.report, "with --run: run A's HTML report, run B drawn as a ghost beside it")
      ->type_name("FILE");
  diffc->add_option("--plc-a", diffo.plc_a, "with --run: run A's --plc scenario")->type_name("FILE");
  diffc->add_option("--plc-b", diffo.plc_b, "with --run: run B's --plc scenario")->type_name("FILE");
  diffc->add_option("--rows", diffo.rows, "rows per table on stdout")->check(number_at_least(1, true));
  diffc->add_option("--max-time", diffo.max_time_s, "with --run: simulated-time limit of each run in seconds")
      ->check(number_at_least(0.001, false));
  diffc->footer("B is compared against A (B - A). Exit 0: compared, 1: a run ended with an error or a limit, 2: bad "
                "usage or an input that is no final state (docs/cli.md).");

  ParseOptions parse;
  auto* parsec = app.add_subcommand("parse", "Decode an NC program and print diagnostics");
  parsec->add_option("PROGRAM", parse.program, "NC program")->required();
  parsec->add_flag("--json", parse.json, "print the decoded blocks as JSON lines");
  parsec->add_option("--machine", parse.machine, "take axis and spindle names from this machine");
  parsec->add_option("--channel", parse.channel, "channel of --machine (1-based)")->check(number_at_least(1, true));
  parsec->add_option("--max-wall", parse.max_wall_s, "wall-clock limit in seconds")
      ->check(number_at_least(0.001, false));
  parsec->add_option("--cycles", parse.cycles, "search DIR for L CYCLE files (after --machine's cycle_path[i]); repeat")
      ->allow_extra_args(false);

  FitOptions fit;
  auto* fitc = app.add_subcommand("fit-curve", "Coefficients b1 b2 b3 of a spindle acceleration curve");
  fitc->add_option("TYPE", fit.type, "hyperbola or polynomial")
      ->required()
      ->check(CLI::IsMember({"hyperbola", "polynomial"}));
  fitc->add_option("--n-grenz", fit.limit_speed_deg_s, "limit speed n_grenz in deg/s")
      ->required()
      ->check(number_at_least(0, false));
  fitc->add_option("--a-konst", fit.const_accel_deg_s2, "constant acceleration below n_grenz in deg/s^2")
      ->required()
      ->check(number_at_least(0, false));
  fitc->add_option("--point", fit.points, "speed,acceleration above n_grenz (deg/s,deg/s^2); repeat")
      ->required();

  InitOptions init;
  auto* initc = app.add_subcommand("init", "Write a machine folder to start from (the milling or lathe example)");
  initc->add_option("DIR", init.folder, "new or empty folder")->required();
  bool mill_flag = false;
  auto* mill = initc->add_flag("--mill", mill_flag, "a 3-axis milling machine with two spindles (the default)");
  initc->add_flag("--lathe", init.lathe, "a 2-axis lathe with a 3-stage main spindle")->excludes(mill);

  ServeOptions serve;
  auto* servec = app.add_subcommand("serve", "Run the kernel live behind a browser HMI and a JSON API (docs/api.md)");
  servec->add_option("MACHINE", serve.machine, "machine folder (with startup.lis)")->required();
  servec->add_option("PROGRAM", serve.programs, "programs to load (channel 1, 2, ...); cycle start starts them");
  servec->add_option("--bind", serve.bind, "address to listen on (default 127.0.0.1; others need --token-file)");
  servec->add_option("--port", serve.port, "TCP port (0: a free one; the printed URL names it)");
  servec->add_option("--token-file", serve.token_file, "read the access token (>= 32 characters) from FILE");
  servec->add_option("--programs", serve.folders, "folder whose programs may be loaded; repeat")->allow_extra_args(false);
  servec->add_option("--uploads", serve.uploads, "folder for uploaded programs (default: a new temporary folder)");
  servec->add_option("--speed", serve.speed, "simulated seconds per wall second (1: real time), or max");
  servec->add_flag("!--no-realtime", serve.realtime, "do not ask for real-time scheduling and locked memory");
  servec->add_flag("--strict", serve.strict_keys, kStrictHelp);
  servec->add_flag("--paused", serve.paused, "start with the kernel's cycles paused (step them from the API)");
  servec->add_option("--max-clients", serve.max_clients, "connections with the token served at once (default 8)")
      ->check(number_at_least(1, true));
  servec->add_option("--max-anonymous", serve.max_anonymous,
                     "connections per address that have sent no token yet (default 4)")
      ->check(number_at_least(1, true));
  servec->add_option("--header-timeout", serve.header_timeout_s,
                     "seconds a connection has for a complete request until one had the token (default 5)")
      ->check(number_at_least(0.1, false));
  servec->add_option("--rate", serve.rate, "requests per second per connection (default 50)")
      ->check(number_at_least(1, false));
  servec->add_option("--max-program", serve.max_program_bytes, "largest program file in bytes (default 4 MiB)")
      ->check(number_at_least(1, true));
  servec->add_option("--max-wall", serve.max_wall_s, "stop serving after this many seconds")
      ->check(number_at_least(0.001, false));

  std::string lookup;
  auto* params = app.add_subcommand("params", "Print every accepted list key as a markdown table");
  params->add_option("KEY", lookup, "only the keys containing KEY (or with this P-... ID)");
  auto* errors = app.add_subcommand("errors", "Print every diagnostic ID as a markdown table");
  errors->add_option("WORD", lookup,
                     "only the IDs whose number, name, cause or remedy contains WORD (case-insensitive; "
                     "quote several words: \"software limit\")");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "nck: error 940001: {}{}\nRun 'nck --help' for usage.\n", e.what(), did_you_mean(app, argc, argv));
    return 2;
  }
  int code = 2;
  try {
    if (*check) code = check_command(checko);
    if (*runc) code = run_simulation(run);
    if (*servec) code = serve_command(serve);
    if (*diffc) code = diff_command(diffo);
    if (*parsec) code = parse_program(parse);
    if (*fitc) code = fit_curve(fit);
    if (*params) code = print_parameters(lookup);
    if (*errors) code = print_errors(lookup);
    if (*initc) code = init_machine(init);
  } catch (const std::exception& e) {  // never an abort: a diagnostic (if stderr takes it) and exit 2
    std::fprintf(stderr, "nck: error %u: %s\n", number(ErrorId::AppInternalError), e.what());
    return 2;
  }
  if (!stdout_written()) code = 2;
  // A stop signal during a command that does not watch for it ends it with
  // the signal's code once the command is done.
  return signal_exit_code() != 0 && code != 2 ? signal_exit_code() : code;
}

}  // namespace nck::app
