#include "diff_command.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <unistd.h>

#include "nck/output/output_writers.hpp"
#include "nck/run/path_track.hpp"
#include "final_diff.hpp"
#include "run_command.hpp"

namespace nck::app {
namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;

constexpr std::size_t kLargestPathDifferences = 10;
constexpr std::size_t kGhostPoints = 60000;  // as many as the report's own backplot keeps

void print_diagnostic(const Diagnostic& d) { fmt::print(stderr, "{}\n", format(d)); }

int print_diff(const ojson& diff, const DiffOptions& opt) {
  if (opt.json) fmt::print("{}\n", dump_json(diff, 1));
  else fmt::print("{}", diff_table(diff, opt.rows));
  return 0;
}

// A temporary folder of this process for the runs' final states; removed on return.
struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / fmt::format("nck-diff-{}", ::getpid());
    std::error_code ec;
    fs::remove_all(path, ec);
    fs::create_directories(path, ec);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

struct OneRun {
  int exit_code = 2;
  PathTrack track;
  std::expected<nlohmann::json, Diagnostic> final = std::unexpected(Diagnostic{});
};

// One run of nck run in this process, its final state in `dir`.
void run_one(const std::string& label, const std::string& machine, const std::string& program, const std::string& plc,
             const fs::path& dir, const DiffOptions& opt, const ojson* ghost, OneRun& r) {
  fmt::print(stderr, "nck diff: run {}: {} {}\n", label, machine, program);
  RunOptions run;
  run.machine = machine;
  run.programs = {program};
  run.plc = plc;
  run.final_state = (dir / (label + ".json")).string();
  run.max_time_s = opt.max_time_s;
  run.progress = false;
  run.track = &r.track;
  if (ghost) {
    run.report = opt.report;
    run.ghost = ghost;
  }
  r.exit_code = run_simulation(run);
  if (r.exit_code == 2 || r.exit_code >= 128) {
    r.final = std::unexpected(make_diagnostic(
        ErrorId::AppDiffRunFailed, SourceLoc{program, 0, 0},
        fmt::format("run {} on {} did not run to an end (exit {}); see the messages above", label, machine, r.exit_code)));
    return;
  }
  r.final = load_final(run.final_state);
}

// B's part of the report: its path as a ghost, its times to compare with.
ojson ghost_of(const DiffOptions& opt, const OneRun& b) {
  const nlohmann::json& f = *b.final;
  ojson causes = ojson::array();
  for (const auto& ch : f["time_by_cause"]["channels"]) causes.push_back(ojson::parse(ch.value("causes", nlohmann::json::array()).dump()));
  return {{"label", fmt::format("B: {} {}", opt.inputs[2], fs::path(opt.inputs[3]).filename().string())},
          {"time_s", f["time"]},
          {"end", f.value("end", "")},
          {"causes", causes},
          {"path", b.track.ghost_json(kGhostPoints)}};
}

int diff_runs(const DiffOptions& opt) {
  const TempDir dir;
  OneRun a, b;
  run_one("B", opt.inputs[2], opt.inputs[3], opt.plc_b, dir.path, opt, nullptr, b);
  if (!b.final) return print_diagnostic(b.final.error()), 2;
  const ojson ghost = ghost_of(opt, b);
  run_one("A", opt.inputs[0], opt.inputs[1], opt.plc_a, dir.path, opt, opt.report.empty() ? nullptr : &ghost, a);
  if (!a.final) return print_diagnostic(a.final.error()), 2;
  ojson diff = diff_finals(*a.final, *b.final);
  diff["path"] = compare_paths(a.track, b.track, kLargestPathDifferences);
  print_diff(diff, opt);
  return a.exit_code != 0 || b.exit_code != 0 ? 1 : 0;
}

}  // namespace

int diff_command(const DiffOptions& opt) {
  const std::size_t want = opt.run ? 4 : 2;
  if (opt.inputs.size() != want) {
    fmt::print(stderr, "nck: error {}: nck diff {} takes {} arguments ({}), not {}\n", number(ErrorId::AppBadUsage),
               opt.run ? "--run" : "", want,
               opt.run ? "MACHINE_A PROGRAM_A MACHINE_B PROGRAM_B" : "A.json B.json", opt.inputs.size());
    return 2;
  }
  if (!opt.run && (!opt.report.empty() || !opt.plc_a.empty() || !opt.plc_b.empty())) {
    fmt::print(stderr, "nck: error {}: --report, --plc-a and --plc-b belong to nck diff --run\n",
               number(ErrorId::AppBadUsage));
    return 2;
  }
  if (opt.run) return diff_runs(opt);
  auto a = load_final(opt.inputs[0]);
  auto b = load_final(opt.inputs[1]);
  if (!a) print_diagnostic(a.error());
  if (!b) print_diagnostic(b.error());
  if (!a || !b) return 2;
  return print_diff(diff_finals(*a, *b), opt);
}

}  // namespace nck::app
