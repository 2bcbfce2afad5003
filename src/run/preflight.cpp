#include "nck/run/preflight.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "nck/config/load.hpp"
#include "nck/output/diagnostic_json.hpp"
#include "nck/prep/program_check.hpp"

namespace nck::app {
namespace {

// Every program a regular file, at most one per channel: else the reason.
std::optional<Diagnostic> usage_problem(const PreflightOptions& opt, const config::Machine& m) {
  for (const std::string& p : opt.programs) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec))
      return make_diagnostic(ErrorId::AppBadUsage, {}, fmt::format("the program {} does not exist or is not a file", p));
  }
  if (opt.programs.size() > m.channels.size())
    return make_diagnostic(ErrorId::AppBadUsage, {},
                           fmt::format("{} program(s) given for {} channel(s); give one per channel",
                                       opt.programs.size(), m.channels.size()));
  return std::nullopt;
}

void check_programs(const PreflightOptions& opt, const config::Machine& m, Preflight& out) {
  for (std::size_t ch = 0; ch < opt.programs.size(); ++ch) {
    prep::ProgramCheckResult r = prep::check_program(m, ch, opt.programs[ch], {opt.clamp_index, opt.stop});
    PreflightProgram p{opt.programs[ch], r.blocks, 0, 0};
    for (Diagnostic& d : r.diagnostics) {
      (d.severity == Severity::error ? p.errors : p.warnings) += 1;
      out.found.push_back({std::move(d), ch + 1});
    }
    if (r.stopped) {
      out.stopped = true;
      return;
    }
    out.programs.push_back(std::move(p));
  }
}

}  // namespace

bool Preflight::has_errors() const {
  for (const PreflightFinding& f : found)
    if (f.d.severity == Severity::error) return true;
  return false;
}

Preflight preflight(const PreflightOptions& opt) {
  // Without programs the check says what no program can ask of the machine;
  // with them, each program's check finds where one asks (70252).
  const config::LoadOptions load{opt.strict_keys ? config::KeyPolicy::strict : config::KeyPolicy::lenient,
                                 opt.programs.empty()};
  config::LoadResult loaded = config::load_machine(opt.machine, load);
  Preflight out;
  for (const Diagnostic& d : loaded.diagnostics.items()) out.found.push_back({d, 0});
  out.machine_errors = loaded.diagnostics.error_count();
  out.machine_loaded = loaded.ok();
  if (!loaded.ok()) return out;
  for (const std::string& dir : opt.cycles) loaded.machine->cycle_paths.emplace_back(dir);
  out.bad_usage = usage_problem(opt, *loaded.machine);
  if (!out.bad_usage) check_programs(opt, *loaded.machine, out);
  return out;
}

nlohmann::ordered_json to_json(const PreflightFinding& f) { return diagnostic_json(f.d, f.channel); }

}  // namespace nck::app
