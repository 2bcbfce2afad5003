#include "run_outputs.hpp"

#include <filesystem>
#include <fmt/format.h>
#include <system_error>
#include <utility>

namespace nck::app {
namespace fs = std::filesystem;

namespace {

fs::path resolved(const std::string& p) {
  std::error_code ec;
  const fs::path abs = fs::absolute(p, ec);
  fs::path r = fs::weakly_canonical(abs, ec);
  return ec ? abs.lexically_normal() : r;
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
  return std::nullopt;
}

}  // namespace nck::app
