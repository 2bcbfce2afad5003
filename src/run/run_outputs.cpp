#include "nck/run/run_outputs.hpp"

#include <filesystem>
#include <fstream>
#include <string_view>
#include <fmt/format.h>
#include <system_error>
#include <tuple>
#include <utility>

#include "input_files.hpp"

namespace nck::app {
namespace fs = std::filesystem;

namespace {

fs::path resolved(const std::string& p) {
  std::error_code ec;
  const fs::path abs = fs::absolute(p, ec);
  fs::path r = fs::weakly_canonical(abs, ec);
  return ec ? abs.lexically_normal() : r;
}

// --realtime writes --events and --trace in place, so that they can be
// followed while the run goes on: the target is emptied when the run starts,
// before the program has called any subroutine. Only an nck output of an
// earlier run (its first bytes are `own_start`) or an empty file may be
// emptied then; anything else may be a file the program is about to read.
std::optional<std::string> live_output_over_other_file(const std::string& path, std::string_view own_start,
                                                       const char* option) {
  std::error_code ec;
  if (path == "-" || !fs::is_regular_file(path, ec) || fs::file_size(path, ec) == 0 || ec) return std::nullopt;
  std::string head(own_start.size(), '\0');
  std::ifstream in(path, std::ios::binary);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  if (in && head == own_start) return std::nullopt;
  return fmt::format("{} {} would empty an existing file that is not an nck output before the run starts "
                     "(--realtime writes in place); remove it or choose another name",
                     option, path);
}

}  // namespace

std::optional<std::string> output_path_conflict(const RunOptions& opt) {
  std::vector<std::pair<fs::path, std::string>> inputs;  // path, what it is
  for (const std::string& p : opt.programs) inputs.emplace_back(resolved(p), "the program " + p);
  if (!opt.plc.empty()) inputs.emplace_back(resolved(opt.plc), "the --plc file " + opt.plc);
  std::error_code ec;
  for (fs::recursive_directory_iterator it(opt.machine, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec)) inputs.emplace_back(resolved(it->path().string()), "the machine file " + it->path().string());

  const std::pair<const std::string*, const char*> outputs[] = {
      {&opt.events, "--events"}, {&opt.trace, "--trace"}, {&opt.final_state, "--final"}, {&opt.report, "--report"}};
  std::vector<std::pair<fs::path, const char*>> seen;
  const char* to_stdout = nullptr;
  for (const auto& [path, option] : outputs) {
    if (*path == "-") {
      if (to_stdout) return fmt::format("{} and {} both write to stdout (-)", to_stdout, option);
      to_stdout = option;
    }
    if (path->empty() || *path == "-") continue;
    const fs::path p = resolved(*path);
    for (const auto& [in, what] : inputs)
      if (p == in) return fmt::format("{} {} would overwrite {}", option, *path, what);
    for (const auto& [other, other_option] : seen)
      if (p == other) return fmt::format("{} and {} name the same file {}", other_option, option, *path);
    seen.emplace_back(p, option);
  }
  if (opt.realtime) {
    if (auto e = live_output_over_other_file(opt.events, "{\"t\":", "--events")) return e;
    if (auto e = live_output_over_other_file(opt.trace, "t,", "--trace")) return e;
  }
  return std::nullopt;
}

OutputsOverInputs outputs_over_inputs(const RunOptions& opt, const sim::DryRun& run) {
  InputFiles read;
  for (const std::string& p : opt.programs) read.add(p, "the program " + p);
  if (!opt.plc.empty()) read.add(opt.plc, "the --plc file " + opt.plc);
  read.add_folder(opt.machine, "the machine file ");
  for (std::size_t ch = 0; ch < run.channel_count(); ++ch)
    if (const nc::Decoder* d = run.prep(ch).decoder())
      for (std::size_t id = 0; id < d->file_count(); ++id) {
        const std::string& name = d->file_name(static_cast<std::uint16_t>(id));
        read.add(name, "the file " + name + " that the program read");
      }
  OutputsOverInputs over;
  const std::tuple<const std::string*, const char*, bool*> outputs[] = {
      {&opt.events, "--events", &over.events},
      {&opt.trace, "--trace", &over.trace},
      {&opt.final_state, "--final", &over.final_state},
      {&opt.report, "--report", &over.report}};
  for (const auto& [path, option, refused] : outputs) {
    if (path->empty() || *path == "-") continue;
    if (auto what = read.find(*path)) {
      *refused = true;
      over.messages.push_back(fmt::format("{} {} would replace {}; it was not written", option, *path, *what));
    }
  }
  return over;
}

}  // namespace nck::app
