// The small commands: parse, fit-curve, params, errors.
#include "commands.hpp"

#include <fmt/format.h>

#include "nck/config/load.hpp"
#include "nck/config/parameter_registry.hpp"
#include "nck/nc/block_json.hpp"
#include "nck/output/output_file.hpp"
#include "nck/prep/decoder_setup.hpp"
#include "nck/run/stop_request.hpp"
#include "nck/spindle/accel_curve.hpp"

#include <filesystem>
#include <initializer_list>
#include <set>
#include <sstream>
#include <vector>

namespace nck::app {

namespace {

nc::DecoderConfig default_decoder_config() {
  nc::DecoderConfig d;
  d.axis_names = {"X", "Y", "Z", "A", "B", "C", "U", "V", "W"};
  d.spindle_names = {"S1", "S2", "S3"};
  d.main_spindle = "S1";
  return d;
}

}  // namespace

int parse_program(const ParseOptions& opt) {
  nc::DecoderConfig cfg = default_decoder_config();
  if (!opt.machine.empty()) {
    const config::LoadResult r = config::load_machine(opt.machine);
    if (!r.ok() || opt.channel == 0 || opt.channel > r.machine->channels.size()) {
      for (const Diagnostic& d : r.diagnostics.items()) fmt::print(stderr, "{}\n", format(d));
      fmt::print(stderr, "nck: error 940001: cannot use channel {} of machine {}\n", opt.channel, opt.machine);
      return 2;
    }
    cfg = prep::decoder_config(*r.machine, opt.channel - 1);
  }
  for (const std::string& dir : opt.cycles) cfg.cycle_dirs.emplace_back(dir);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(opt.program, ec)) {  // bad usage, not an NC error
    fmt::print(stderr, "nck: error 940001: the program {} does not exist or is not a file\n", opt.program);
    return 2;
  }
  cfg.continue_after_error = true;  // lint: report every bad block, not only the first
  cfg.stop = &stop_flag();          // SIGINT, SIGTERM, --max-wall
  const WallClockLimit wall(opt.max_wall_s);
  nc::Decoder dec(opt.program, cfg);
  std::size_t blocks = 0;
  std::size_t shown = 0;
  auto show_new = [&] {
    std::fflush(stdout);  // keep blocks and diagnostics in order on a shared terminal
    for (; shown < dec.diagnostics().size(); ++shown)
      fmt::print(stderr, "{}\n", format(dec.diagnostics()[shown]));
  };
  for (;;) {
    nc::Decoder::Result res = dec.next();
    show_new();
    // In lint mode a bad block is dropped and decoding goes on (an error met
    // again in a loop brings no new diagnostic, yet decoding goes on).
    if (res.status == nc::Decoder::Status::error && dec.can_continue()) continue;
    if (res.status != nc::Decoder::Status::block) break;
    ++blocks;
    // A closed pipe (nck parse --json | head) ends the listing; main_cli reports it.
    if (opt.json && !write_stdout(nc::to_json(res.block, dec).dump(-1, ' ', false,
                                                                   nlohmann::json::error_handler_t::replace) +
                                  "\n"))
      break;
    if (res.block.program_end) break;
  }
  if (stop_flag().load()) {
    std::fflush(stdout);
    if (wall.reached())
      fmt::print(stderr, "nck: error {}: the wall-clock limit of {} s was reached after {} block(s)\n",
                 number(ErrorId::AppWallTimeLimit), opt.max_wall_s, blocks);
    else
      fmt::print(stderr, "nck: interrupted after {} block(s)\n", blocks);
    return wall.reached() && stop_signal() == 0 ? 1 : signal_exit_code();
  }
  std::size_t errors = 0;
  for (const Diagnostic& d : dec.diagnostics()) errors += d.severity == Severity::error;
  std::fflush(stdout);
  fmt::print(stderr, "{}: {} block(s), {} error(s)\n", opt.program, blocks, errors);
  return errors == 0 ? 0 : 1;
}

int fit_curve(const FitOptions& opt) {
  std::vector<spindle::CurvePoint> points;
  for (const std::string& p : opt.points) {
    spindle::CurvePoint cp;
    char comma = 0;
    std::istringstream in(p);
    if (!(in >> cp.speed_deg_s >> comma >> cp.accel_deg_s2) || comma != ',' || !(in >> std::ws).eof()) {
      fmt::print(stderr, "nck: error 940001: --point '{}' is not SPEED,ACCEL (deg/s,deg/s^2)\n", p);
      return 2;
    }
    points.push_back(cp);
  }
  auto c = opt.type == "hyperbola"
               ? spindle::fit_hyperbola(opt.limit_speed_deg_s, opt.const_accel_deg_s2, points)
               : spindle::fit_polynomial(opt.limit_speed_deg_s, opt.const_accel_deg_s2, points);
  if (!c) {
    fmt::print(stderr, "nck: error 950011: {}\n", c.error());
    return 2;
  }
  (void)write_stdout(fmt::format("b1 {:.9E}\nb2 {:.9E}\nb3 {:.9E}\n", c->b1, c->b2, c->b3));
  return 0;
}

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The cells of a markdown table row ("| a | b |" -> {"a", "b"}).
std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::size_t from = row.find('|');
  while (from != std::string::npos) {
    const std::size_t to = row.find('|', from + 1);
    if (to == std::string::npos) break;
    std::string cell = row.substr(from + 1, to - from - 1);
    const std::size_t first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
    out.push_back(first == std::string::npos ? std::string() : cell.substr(first, last - first + 1));
    from = to;
  }
  return out;
}

// The table rows of a generated markdown page in which one of the columns
// `searched` contains `lookup` (case-insensitive), or whose first cell is
// one of `also`, under the page's header.
int print_matching_rows(const std::string& markdown, const std::string& lookup,
                        std::initializer_list<std::size_t> searched, const char* what,
                        const std::set<std::string>& also = {}) {
  if (lookup.empty()) {
    (void)write_stdout(markdown);
    return 0;
  }
  std::vector<std::string> lines;
  std::istringstream in(markdown);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::string header, rows;
  const std::string needle = lower(lookup);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const bool is_header = i + 1 < lines.size() && lines[i + 1].starts_with("|---");
    if (is_header && header.empty()) header = lines[i] + "\n" + lines[i + 1] + "\n";
    if (is_header || !lines[i].starts_with("| ")) continue;
    const std::vector<std::string> row = cells(lines[i]);
    if (!row.empty() && also.contains(row[0])) {
      rows += lines[i] + "\n";
      continue;
    }
    for (std::size_t c : searched)
      if (c < row.size() && lower(row[c]).find(needle) != std::string::npos) {
        rows += lines[i] + "\n";
        break;
      }
  }
  if (rows.empty()) {
    fmt::print(stderr, "nck: no {} matches '{}'\n", what, lookup);
    return 1;
  }
  (void)write_stdout(header + rows);
  return 0;
}

// The key cells ("`spindel[i].log_achs_nr`") of the parameters whose
// accepted seed spellings or short forms contain `lookup` (log_achs_no).
std::set<std::string> keys_spelt_like(const std::string& lookup) {
  std::set<std::string> out;
  const std::string needle = lower(lookup);
  for (const config::ParamInfo& p : config::all_parameters())
    for (const std::string& alias : config::alias_patterns(p))
      if (lower(config::display_key(alias)).find(needle) != std::string::npos)
        out.insert("`" + config::display_key(p.key) + "`");
  return out;
}

}  // namespace

int print_parameters(const std::string& lookup) {
  return print_matching_rows(config::parameters_markdown(), lookup, {0, 1}, "list key", keys_spelt_like(lookup));
}

// By ID, name or a word of its description ("940004", "OutputPath",
// "software limit"): a user knows what went wrong before knowing its name.
int print_errors(const std::string& lookup) {
  return print_matching_rows(errors_markdown(), lookup, {0, 2, 3, 4}, "diagnostic ID, name or description");
}

}  // namespace nck::app
